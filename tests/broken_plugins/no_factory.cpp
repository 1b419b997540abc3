// libunimap_payload_no_factory.so: exports the ABI version but no factory
// (the loader must answer NotAPluginError).
#include <cstdint>

#include <boost/config.hpp>

#include "unimap/Version.hpp"

extern "C" BOOST_SYMBOL_EXPORT const std::uint32_t unimap_payload_abi_version;
extern "C" const std::uint32_t unimap_payload_abi_version = ::unimap::kPayloadAbiVersion;
