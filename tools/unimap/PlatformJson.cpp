#include "PlatformJson.hpp"

#include "unimap/Platform.hpp"

namespace unimap::cli {

JsonObject PlatformParametersJson(const std::string& platform_file) {
  const Platform platform = LoadPlatform(platform_file);
  JsonObject parameters;
  for (const EffectiveParameter& p : platform.effective) {
    JsonObject o;
    o.Add("value", ToString(p.value));
    o.Add("symbol", p.spec.symbol);
    o.Add("source", p.source == ParameterSource::kPlatformFile ? platform.file + ":" + std::to_string(p.line)
                                                               : std::string("plugin default"));
    o.Add("meaning", p.spec.description);
    parameters.Add(p.spec.key, o);
  }
  // The mapper settings the file changes (`unimap config` lists the rest).
  for (const ParameterOverride& setting : platform.mapper_settings) {
    JsonObject o;
    o.Add("value", ToString(setting.value));
    o.Add("source", platform.file + ":" + std::to_string(setting.line));
    parameters.Add("mapper." + setting.key, o);
  }
  return parameters;
}

}  // namespace unimap::cli
