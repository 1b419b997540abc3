#include "PlatformJson.hpp"

#include "unimap/Platform.hpp"

namespace unimap::cli {

Json PlatformParametersJson(const std::string& platform_file) {
  const Platform platform = LoadPlatform(platform_file);
  Json parameters = Json::object();
  for (const EffectiveParameter& p : platform.effective) {
    Json o = Json::object();
    o["value"] = ToString(p.value);
    o["symbol"] = p.spec.symbol;
    o["source"] = p.source == ParameterSource::kPlatformFile ? platform.file + ":" + std::to_string(p.line)
                                                             : std::string("plugin default");
    o["meaning"] = p.spec.description;
    parameters[p.spec.key] = o;
  }
  // The mapper settings the file changes (`unimap config` lists the rest).
  for (const ParameterOverride& setting : platform.mapper_settings) {
    Json o = Json::object();
    o["value"] = ToString(setting.value);
    o["source"] = platform.file + ":" + std::to_string(setting.line);
    parameters["mapper." + setting.key] = o;
  }
  return parameters;
}

}  // namespace unimap::cli
