#include "SceneScaleReport.hpp"

#include <cstdio>

#include "unimap/CoreParameters.hpp"

namespace unimap::cli {
namespace {

double PlatformVoxel(const Platform& platform) {
  return CoreParameters::FromMap(platform.parameters).distance_map_resolution_m;
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g m", value);
  return text;
}

}  // namespace

std::string SceneVoxelLine(const Platform& platform, const pipeline::SceneScale& scene, double voxel_m) {
  const double platform_voxel_m = PlatformVoxel(platform);
  if (scene.returns == 0) {
    return "map voxel: " + Metres(voxel_m) + " (the platform's; the first scans hold no return to size the scene)";
  }
  const std::string median =
      "the first " + std::to_string(scene.scans) + " scans' median range " + Metres(scene.median_range_m);
  if (voxel_m == platform_voxel_m) return "map voxel: " + Metres(voxel_m) + " (the platform's; " + median + ")";
  char limit[16];
  std::snprintf(limit, sizeof(limit), "%g", pipeline::kMaxVoxelsAcrossScene);
  return "map voxel: " + Metres(voxel_m) + " (" + median + " spans more than " + limit + " of the platform's " +
         Metres(platform_voxel_m) + " voxels)";
}

Json SceneScaleJson(const Platform& platform, const pipeline::SceneScale& scene, double voxel_m) {
  Json json = Json::object();
  json["median_range_m"] = scene.median_range_m;
  json["returns"] = scene.returns;
  json["scans"] = scene.scans;
  json["platform_voxel_m"] = PlatformVoxel(platform);
  json["voxel_m"] = voxel_m;
  json["max_voxels_across"] = pipeline::kMaxVoxelsAcrossScene;
  return json;
}

}  // namespace unimap::cli
