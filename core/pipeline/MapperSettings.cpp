#include "pipeline/MapperSettings.hpp"

#include <cstddef>
#include <map>

#include "options/SettingsOverrides.hpp"
#include "unimap/CoreParameters.hpp"

namespace unimap::pipeline {
namespace {

constexpr const char* kSection = "mapper";

options::VisitAll VisitOf(MapperOptions* options) {
  return [options](options::FieldVisitor& v) { options->VisitFields(v); };
}

// The values that follow another field, unless the file sets them.
void Derive(const options::SettingsOverrides& settings, bool clamp_follows_gpf, MapperOptions* options) {
  if (clamp_follows_gpf && !settings.Sets("map.clamp_distance_m")) options->localizer.ClampFieldAtLikelihood();
  options->submaps.map = options->localizer.map;
}

// base with every setting applied and derived values updated; throws
// ConfigError for the first setting that leaves the options invalid.
MapperOptions Apply(const options::SettingsOverrides& settings, const MapperOptions& base, bool clamp_follows_gpf) {
  MapperOptions result = base;
  settings.CheckKeys(VisitOf(&result));
  settings.ApplyAll(VisitOf(&result));
  Derive(settings, clamp_follows_gpf, &result);
  std::string why;
  if (result.IsValid(&why)) return result;
  // Blame the first setting after which the options are invalid.
  MapperOptions partial = base;
  for (std::size_t i = 0; i < settings.settings().size(); ++i) {
    settings.Apply(i, VisitOf(&partial));
    MapperOptions derived = partial;
    Derive(settings, clamp_follows_gpf, &derived);
    if (!derived.IsValid(&why)) throw settings.Error(i, why);
  }
  throw settings.Error(settings.settings().size() - 1, why);
}

options::SettingsOverrides SettingsOf(const Platform& platform) {
  return options::SettingsOverrides(platform.file, kSection, platform.mapper_settings);
}

}  // namespace

MapperOptions MapperOptionsFor(const Platform& platform) {
  const MapperOptions base = MapperOptions::FromPlatform(CoreParameters::FromMap(platform.parameters));
  return Apply(SettingsOf(platform), base, true);
}

LocalizerOptions PriorMapOptionsFor(const Platform& platform) {
  MapperOptions base;
  base.localizer = LocalizerOptions::ForPriorMap(CoreParameters::FromMap(platform.parameters));
  base.submaps.map = base.localizer.map;
  return Apply(SettingsOf(platform), base, false).localizer;
}

std::vector<MapperSettingRow> ListMapperSettings(const Platform& platform) {
  MapperOptions defaults;
  MapperOptions derived = MapperOptions::FromPlatform(CoreParameters::FromMap(platform.parameters));
  MapperOptions effective = Apply(SettingsOf(platform), derived, true);
  const std::vector<options::FieldRow> default_rows = options::ListFields(VisitOf(&defaults));
  const std::vector<options::FieldRow> derived_rows = options::ListFields(VisitOf(&derived));
  const std::vector<options::FieldRow> rows = options::ListFields(VisitOf(&effective));
  std::map<std::string, int> lines;
  for (const ParameterOverride& setting : platform.mapper_settings) lines.emplace(setting.key, setting.line);
  std::vector<MapperSettingRow> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    MapperSettingRow row{std::string(kSection) + "." + rows[i].key, rows[i].value, rows[i].unit, "default"};
    if (const auto it = lines.find(rows[i].key); it != lines.end()) {
      row.source = platform.file + ":" + std::to_string(it->second);
    } else if (rows[i].value != derived_rows.at(i).value) {
      row.source = "derived";  // follows a field the file sets
    } else if (derived_rows.at(i).value != default_rows.at(i).value) {
      row.source = "platform";  // MapperOptions::FromPlatform's value for the platform's parameters
    }
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace unimap::pipeline
