// libunimap_payload_test_valid.so: a valid plugin, exported the normal way.
#include "MinimalPlugin.hpp"
#include "unimap/PluginExport.hpp"

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap_test::MinimalPlugin)
