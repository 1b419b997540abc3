#include "PlatformFileWriter.hpp"

#include <sstream>
#include <type_traits>
#include <variant>

#include <yaml-cpp/yaml.h>

namespace unimap {
namespace {

void EmitValue(YAML::Emitter& out, const ParameterValue& value) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::vector<double>>) {
          out << YAML::Flow << YAML::BeginSeq;
          for (const double x : v) out << x;
          out << YAML::EndSeq;
        } else {
          out << v;
        }
      },
      value);
}

void EmitSection(YAML::Emitter& out, const char* name, const std::vector<ParameterOverride>& settings) {
  if (settings.empty()) return;
  out << YAML::Key << name << YAML::Value << YAML::BeginMap;
  for (const ParameterOverride& s : settings) {
    out << YAML::Key << s.key << YAML::Value;
    EmitValue(out, s.value);
  }
  out << YAML::EndMap;
}

}  // namespace

std::string WritePlatformYaml(const std::string& plugin, const std::vector<ParameterOverride>& parameters,
                              const std::vector<ParameterOverride>& mapper_settings, const std::string& comment) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "plugin" << YAML::Value << plugin;
  EmitSection(out, "parameters", parameters);
  EmitSection(out, "mapper", mapper_settings);
  out << YAML::EndMap;
  std::ostringstream text;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) text << "# " << line << '\n';
  text << out.c_str() << '\n';
  return text.str();
}

}  // namespace unimap
