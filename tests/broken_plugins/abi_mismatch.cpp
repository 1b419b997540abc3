// libunimap_payload_abi_mismatch.so: symbols written by hand (not with
// UNIMAP_EXPORT_PAYLOAD_PLUGIN) claiming the next ABI version; the factory
// must never be called (the loader must answer AbiMismatchError).
#include <cstdint>
#include <cstdlib>
#include <memory>

#include <boost/dll/alias.hpp>

#include "unimap/PayloadPlugin.hpp"
#include "unimap/Version.hpp"

extern "C" BOOST_SYMBOL_EXPORT const std::uint32_t unimap_payload_abi_version;
extern "C" const std::uint32_t unimap_payload_abi_version = ::unimap::kPayloadAbiVersion + 1;

namespace unimap_test {
// Aborts: reaching it means the loader ignored the version mismatch.
std::unique_ptr<unimap::PayloadPlugin> CreateFromTheFuture() { std::abort(); }
}  // namespace unimap_test

BOOST_DLL_ALIAS(unimap_test::CreateFromTheFuture, unimap_create_payload_plugin)
