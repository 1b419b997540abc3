#pragma once
// The payload plugin conformance suite (GoogleTest, value-parameterised over
// plugin library paths). Register it for a plugin with the CMake helper
// unimap_add_conformance_test(<name>), or run any built plugin with
//   <name>_conformance --plugin=/path/to/libunimap_payload_x.so
#include <string>
#include <vector>

#include "unimap/Export.hpp"

namespace unimap::conformance {

// Plugin libraries the suite runs against: default_plugins, plus every
// --plugin=PATH argument and every ':'-separated entry of
// UNIMAP_CONFORMANCE_PLUGINS (these replace the defaults when given). An
// entry naming an existing file is made absolute; any other entry is left
// for PluginLoader to resolve as a payload name. Initialises GoogleTest with
// the remaining arguments and runs all tests; each test is named after its
// plugin ("Payload/PayloadConformanceTest.Loads/<name>"). Returns 2 when
// no plugin is given.
UNIMAP_CONFORMANCE_API int RunMain(int argc, char** argv, std::vector<std::string> default_plugins);

// The library paths the suite was set up with (for the test instantiation).
UNIMAP_CONFORMANCE_API const std::vector<std::string>& PluginPaths();

}  // namespace unimap::conformance
