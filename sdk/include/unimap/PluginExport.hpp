#pragma once
// UNIMAP_EXPORT_PAYLOAD_PLUGIN(Class): the one line a plugin library needs.
// It exports the ABI version the plugin was built against and, through
// BOOST_DLL_ALIAS, the factory `unimap_create_payload_plugin`.
#include <cstdint>
#include <memory>

#include <boost/dll/alias.hpp>

#include "unimap/PayloadPlugin.hpp"
#include "unimap/Version.hpp"

namespace unimap {
// Signature of the exported factory.
using PayloadPluginFactory = std::unique_ptr<PayloadPlugin>();
}  // namespace unimap

#define UNIMAP_EXPORT_PAYLOAD_PLUGIN(PluginClass)                                                            \
  extern "C" BOOST_SYMBOL_EXPORT const std::uint32_t unimap_payload_abi_version;                             \
  extern "C" const std::uint32_t unimap_payload_abi_version = ::unimap::kPayloadAbiVersion;                  \
  namespace unimap_payload_export {                                                                          \
  std::unique_ptr<::unimap::PayloadPlugin> CreatePayloadPlugin() { return std::make_unique<PluginClass>(); } \
  }                                                                                                          \
  BOOST_DLL_ALIAS(unimap_payload_export::CreatePayloadPlugin, unimap_create_payload_plugin)
