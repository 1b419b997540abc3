#pragma once
#include <string>
#include <vector>

#include "pipeline/LocalizerOptions.hpp"
#include "pipeline/MapperOptions.hpp"
#include "pipeline/SceneScale.hpp"
#include "unimap/Platform.hpp"

namespace unimap::pipeline {

// One mapper setting as `unimap config` lists it.
struct MapperSettingRow {
  std::string key;     // "mapper.gpf.num_particles"
  std::string value;   // effective value
  std::string unit;    // "" when it has none
  std::string source;  // "file:line"; "derived" (follows a field the file sets); "platform"
                       // (MapperOptions::FromPlatform's value for the platform's parameters); "default"
};

// MapperOptions::FromPlatform with the platform file's `mapper:` section
// applied (MapperOptions::VisitFields names the keys). Values derived from
// another field follow it unless the file sets them too: the distance map's
// clamp follows gpf.clamp_distance_m, each submap's map the `map` section.
// Throws ConfigError(file, line, "mapper.<key>", reason) for an unknown key,
// a key set elsewhere, a wrong type, or a value the options reject
// (IsValid; the first setting that makes them invalid is named).
MapperOptions MapperOptionsFor(const Platform& platform);
// The same with the platform's distance-map voxel coarsened to the scene
// (SceneVoxel with kMaxVoxelsAcrossScene); a scene without returns keeps it.
// A `mapper:` value that is invalid only at the coarser voxel throws
// ConfigError naming the key, the voxel and why the scene chose it.
MapperOptions MapperOptionsFor(const Platform& platform, const SceneScale& scene);
// LocalizerOptions::ForPriorMap (unimap localize) with the section's
// localiser keys applied; the other keys are checked but have no effect.
LocalizerOptions PriorMapOptionsFor(const Platform& platform);
// Every key of the section with its effective value and where it came from.
std::vector<MapperSettingRow> ListMapperSettings(const Platform& platform);

}  // namespace unimap::pipeline
