// libunimap_payload_factory_null.so: the right ABI version and a factory that
// returns nullptr (the loader must answer PluginFactoryError).
#include <cstdint>
#include <memory>

#include <boost/dll/alias.hpp>

#include "unimap/PayloadPlugin.hpp"
#include "unimap/Version.hpp"

extern "C" BOOST_SYMBOL_EXPORT const std::uint32_t unimap_payload_abi_version;
extern "C" const std::uint32_t unimap_payload_abi_version = ::unimap::kPayloadAbiVersion;

namespace unimap_test {
// Returns no plugin at all.
std::unique_ptr<unimap::PayloadPlugin> CreateNothing() { return nullptr; }
}  // namespace unimap_test

BOOST_DLL_ALIAS(unimap_test::CreateNothing, unimap_create_payload_plugin)
