#pragma once
// A platform's effective parameters for run.json, so that the report can say
// what every parameter was and where it came from.
#include <string>

#include "Json.hpp"

namespace unimap::cli {

// {"<key>": {"value", "symbol", "source" ("plugin default" or "FILE:LINE"),
// "meaning"}, ...} in the plugin's order, from LoadPlatform(platform_file).
// Throws ConfigError as LoadPlatform does.
Json PlatformParametersJson(const std::string& platform_file);

}  // namespace unimap::cli
