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
  return parameters;
}

}  // namespace unimap::cli
