#pragma once
// Internal to libunimap_config (exported for the tools, not installed): the
// one place that writes platform-file YAML (PlatformFile reads it).
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/Platform.hpp"

namespace unimap {

// The text of a platform file that PlatformFile::Parse reads back to the same
// plugin, parameters and mapper settings (keys written dotted, one per line,
// in the order given; numbers with enough digits to round-trip). comment:
// lines put first as YAML comments ("# " added to each).
UNIMAP_CORE_API std::string WritePlatformYaml(const std::string& plugin,
                                              const std::vector<ParameterOverride>& parameters,
                                              const std::vector<ParameterOverride>& mapper_settings,
                                              const std::string& comment);

}  // namespace unimap
