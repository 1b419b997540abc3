#include "pipeline/MapperSettings.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <map>
#include <string>

#include "options/SettingsOverrides.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"

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
  if (settings.settings().empty()) throw ConfigError("", 0, "", "mapper options: " + why);
  throw settings.Error(settings.settings().size() - 1, why);
}

// Keys of the `map` section that only the single-map localiser's
// map::DistanceMap reads (unimap localize's prior map): the submaps of
// unimap run and the Mapper API keep their surfaces in
// map::SurfaceDistanceLayer, which does not, so setting one there would
// change nothing. Each with what the submaps do instead and where it applies.
constexpr const char* kPriorMapOnly = "it applies to unimap localize's prior map only";
constexpr const char* kNoBox = "compute their fields in blocks around the surfaces, not in a box";
struct UnreadKey {
  const char* key;
  const char* instead;                  // what the submaps do
  const char* applies = kPriorMapOnly;  // where the key applies
};
constexpr UnreadKey kUnreadBySubmaps[] = {
    {"map.subvoxel_surfaces", "always measure to the surface inside each voxel"},
    {"map.signed_surfaces", "always measure unsigned distances"},
    {"map.cell_planes", "keep no cell planes", "unimap localize sets it with --point-to-plane"},
    {"map.recenter_fraction", kNoBox},
    {"map.growth_margin_m", kNoBox},
    {"map.max_edt_cells", kNoBox},
    {"map.max_occupied_voxels", "load no .bt map"},
    {"map.occupancy_threshold", "call a voxel occupied above probability 0.5"},
    {"map.clear_occupied_only", "always lower only voxels that are occupied"},
    {"map.discretize_rays", "always cast one ray per voxel hit"},
};

// Throws ConfigError for the first setting the submaps would not read.
void RejectUnreadBySubmaps(const options::SettingsOverrides& settings) {
  for (std::size_t i = 0; i < settings.settings().size(); ++i) {
    for (const UnreadKey& unread : kUnreadBySubmaps) {
      if (settings.settings()[i].key != unread.key) continue;
      throw settings.Error(
          i, std::string("not read by unimap run's submaps, which ") + unread.instead + "; " + unread.applies);
    }
  }
}

options::SettingsOverrides SettingsOf(const Platform& platform) {
  return options::SettingsOverrides(platform.file, kSection, platform.mapper_settings);
}

}  // namespace

MapperOptions MapperOptionsFor(const Platform& platform) { return MapperOptionsFor(platform, SceneScale{}); }

MapperOptions MapperOptionsFor(const Platform& platform, const SceneScale& scene) {
  CoreParameters core = CoreParameters::FromMap(platform.parameters);
  const double platform_voxel_m = core.distance_map_resolution_m;
  // At most the largest voxel a platform file may set (CoreParameters: a
  // quarter of the box, 2 m), so that the derived options stay valid.
  core.distance_map_resolution_m = SceneVoxel(platform_voxel_m, scene.median_range_m, kMaxVoxelsAcrossScene,
                                              std::min(core.distance_map_max_range_m / 4.0, kMaxSceneVoxelM));
  const MapperOptions base = MapperOptions::FromPlatform(core);
  const options::SettingsOverrides settings = SettingsOf(platform);
  try {
    MapperOptions options = Apply(settings, base, true);
    RejectUnreadBySubmaps(settings);
    return options;
  } catch (const ConfigError& e) {
    if (core.distance_map_resolution_m == platform_voxel_m) throw;
    // A `mapper:` value that holds at the platform's voxel but not at the
    // scene's: say which voxel and why it was chosen.
    char context[200];
    std::snprintf(context, sizeof(context),
                  " (with the map voxel of %g m that the scene's scale chose: the first scans' median range of "
                  "%.3g m spans more than %g of the platform's %g m voxels)",
                  core.distance_map_resolution_m, scene.median_range_m, kMaxVoxelsAcrossScene, platform_voxel_m);
    throw ConfigError(e.file(), e.line(), e.key(), e.reason() + context);
  }
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
