#include "WorldMap.hpp"

#include <chrono>

#include "WorldLoader.hpp"
#include "io/PcdWriter.hpp"
#include "unimap/CoreParameters.hpp"

namespace unimap::sim {

double WorldMapRange(const Platform& platform) {
  if (platform.parameters.Contains("lidar.max_range_m")) return platform.parameters.GetDouble("lidar.max_range_m");
  return CoreParameters::FromMap(platform.parameters).distance_map_max_range_m;
}

WorldMapSummary WriteWorldMap(const Scenario& scenario, const Platform& platform, double duration_s,
                              const std::filesystem::path& file, WorldMapOptions options) {
  const auto start = std::chrono::steady_clock::now();
  const World world = LoadWorld(scenario.world, scenario.world_file);
  const WaypointTrajectory trajectory = scenario.MakeTrajectory();
  options.sampler.max_range_m = WorldMapRange(platform);
  const std::vector<Eigen::Vector3d> viewpoints = TrajectoryViewpoints(trajectory, duration_s, options.viewpoints);
  const std::vector<Eigen::Vector3d> points = SurfaceSampler(world, options.sampler).Sample(viewpoints);

  std::vector<Eigen::Vector3f> points_world;
  points_world.reserve(points.size());
  for (const Eigen::Vector3d& p : points) points_world.push_back(p.cast<float>());
  io::WritePcdXyz(file, points_world);

  WorldMapSummary summary;
  summary.file = file;
  summary.viewpoints = viewpoints.size();
  summary.points = points_world.size();
  summary.max_range_m = options.sampler.max_range_m;
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace unimap::sim
