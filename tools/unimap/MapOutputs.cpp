#include "MapOutputs.hpp"

#include <algorithm>
#include <cmath>

#include <cstdio>

#include <octomap/OcTree.h>

#include "MapQualityMetrics.hpp"
#include "eval/AtomicFile.hpp"
#include "eval/MapQuality.hpp"
#include "eval/TrajectoryErrors.hpp"
#include "io/KittiTrajectoryWriter.hpp"
#include "io/PcdWriter.hpp"
#include "io/PlyWriter.hpp"
#include "io/TumTrajectory.hpp"
#include "map/OctomapWriter.hpp"

namespace unimap::cli {
namespace {

// The pose of a trajectory nearest to time_s, or nullptr when none lies within max_dt_s.
const StampedPose* Nearest(const std::vector<StampedPose>& poses, double time_s, double max_dt_s) {
  auto it =
      std::lower_bound(poses.begin(), poses.end(), time_s, [](const StampedPose& p, double t) { return p.time_s < t; });
  const StampedPose* best = nullptr;
  if (it != poses.end()) best = &*it;
  if (it != poses.begin()) {
    const StampedPose* before = &*(it - 1);
    if (best == nullptr || time_s - before->time_s < best->time_s - time_s) best = before;
  }
  if (best == nullptr || std::abs(best->time_s - time_s) > max_dt_s) return nullptr;
  return best;
}

// Errors of estimate (moved into the truth's frame by T_truth_estimate) against truth.
PositionErrorAt ErrorsAt(const Eigen::Isometry3d& T_truth_estimate, const StampedPose& estimate,
                         const StampedPose& truth) {
  const Eigen::Vector3d d = (T_truth_estimate * estimate.T_map_body).translation() - truth.T_map_body.translation();
  return {std::abs(d.z()), d.norm()};
}

// One line per closure (the report draws them): time, scan position, submap origin.
void WriteLoopClosures(const std::filesystem::path& file, const std::vector<pipeline::LoopClosureLink>& links) {
  std::string text = "# time_s scan_x scan_y scan_z submap_x submap_y submap_z (map frame, m)\n";
  char line[256];
  for (const pipeline::LoopClosureLink& l : links) {
    std::snprintf(line, sizeof(line), "%.6f %.4f %.4f %.4f %.4f %.4f %.4f\n", l.time_s, l.scan_world.x(),
                  l.scan_world.y(), l.scan_world.z(), l.submap_world.x(), l.submap_world.y(), l.submap_world.z());
    text += line;
  }
  eval::WriteFileAtomically(file, text);
}

Json ErrorsJson(const PositionErrorAt& e) {
  Json o = Json::object();
  o["height_error_m"] = e.height_error_m;
  o["position_error_m"] = e.position_error_m;
  return o;
}

}  // namespace

Json WriteMapOutputs(const std::filesystem::path& out_dir, const pipeline::Mapper& mapper,
                     const MapOutputOptions& options) {
  const std::vector<StampedPose> trajectory = mapper.OptimizedTrajectory();
  io::WriteTumTrajectory(out_dir / "trajectory.tum", trajectory);
  io::WriteKittiTrajectory(out_dir / "trajectory_kitti.txt", trajectory);
  if (options.T_cam_lidar && !trajectory.empty()) {
    const Eigen::Isometry3d& Tr = *options.T_cam_lidar;
    const Eigen::Isometry3d T_lidar0_map = (trajectory.front().T_map_body * options.T_body_lidar).inverse();
    std::vector<StampedPose> camera;
    camera.reserve(trajectory.size());
    for (const StampedPose& pose : trajectory) {
      const Eigen::Isometry3d T_lidar0_lidar = T_lidar0_map * pose.T_map_body * options.T_body_lidar;
      camera.push_back({pose.time_s, Tr * T_lidar0_lidar * Tr.inverse()});
    }
    io::WriteKittiTrajectory(out_dir / "trajectory_kitti_camera.txt", camera);
  }

  std::vector<float> intensities;
  const std::vector<Eigen::Vector3f> points = mapper.MapPoints(options.map_voxel_m, &intensities);
  // The input's intensities as a field of both files, when it had them.
  const std::vector<float>* intensity = intensities.empty() ? nullptr : &intensities;
  io::WritePcdXyz(out_dir / "map.pcd", points, io::PcdEncoding::kBinary, intensity);
  io::WritePly(out_dir / "map.ply", points, intensity);
  octomap::OcTree tree(options.octree_resolution_m);
  for (const Eigen::Vector3f& p : points) tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  map::WriteOctomapBinary(out_dir / "map.bt", tree);
  WriteLoopClosures(out_dir / "loop_closures.csv", mapper.LoopClosureLinks());

  const pipeline::MapperStats s = mapper.stats();
  Json o = Json::object();
  o["key_scans"] = s.key_scans;
  o["submaps"] = static_cast<std::size_t>(s.submaps);
  o["retired_submaps"] = s.retired_submaps;
  o["redundant_submaps"] = s.loop_search.redundant;
  o["retired_submap_points"] = s.retired_points;
  o["retired_submap_mib"] = static_cast<double>(s.retired_bytes) / (1024.0 * 1024.0);
  o["loop_closures"] = s.loop_closures;
  o["optimisations"] = s.optimizations;
  o["optimisation_failures"] = s.optimization_failures;
  o["optimisation_s"] = s.optimization_s;
  o["key_scan_points"] = s.key_scan_points;
  o["map_points_kept"] = s.map_points_kept;
  o["loop_searches"] = s.loop_search.searches;
  o["loop_candidates"] = s.loop_search.candidates;
  o["loop_rejected"] = s.loop_search.rejected;
  o["loop_matchers_built"] = s.loop_search.matchers_built;
  o["map_points"] = points.size();
  o["map_intensity"] = intensity != nullptr;
  o["map_voxel_m"] = options.map_voxel_m;
  o["map_quality"] = MapQualityJson(eval::ComputeMapQuality(points));
  o["map_largest_planes"] = LargestPlanesJson(eval::FindLargestPlanes(points));
  o["messages"] = s.messages;
  return o;
}

std::optional<LoopPointErrors> ComputeLoopPointErrors(const std::vector<StampedPose>& odometry,
                                                      const std::vector<StampedPose>& optimized,
                                                      const std::vector<StampedPose>& truth, double time_s) {
  constexpr double kMaxDt = 0.1;
  const StampedPose* before = Nearest(odometry, time_s, kMaxDt);
  const StampedPose* after = Nearest(optimized, time_s, kMaxDt);
  const StampedPose* true_pose = Nearest(truth, time_s, kMaxDt);
  if (before == nullptr || after == nullptr || true_pose == nullptr) return std::nullopt;
  const StampedPose* true_start = Nearest(truth, odometry.front().time_s, kMaxDt);
  if (true_start == nullptr) return std::nullopt;
  // Start-anchored on position and heading (as drift_percent): both
  // trajectories begin in the local frame, which the first (fixed) graph node keeps.
  const Eigen::Isometry3d T_truth_estimate =
      eval::AnchorTransform(true_start->T_map_body, odometry.front().T_map_body, eval::Anchor::kYawPosition);
  return LoopPointErrors{time_s, ErrorsAt(T_truth_estimate, *before, *true_pose),
                         ErrorsAt(T_truth_estimate, *after, *true_pose)};
}

Json LoopPointJson(const LoopPointErrors& errors) {
  Json o = Json::object();
  o["time_s"] = errors.time_s;
  o["odometry"] = ErrorsJson(errors.odometry);
  o["optimized"] = ErrorsJson(errors.optimized);
  return o;
}

}  // namespace unimap::cli
