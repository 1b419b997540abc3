#include "MapOutputs.hpp"

#include <algorithm>
#include <cmath>

#include <cstdio>

#include <octomap/OcTree.h>

#include "eval/AtomicFile.hpp"
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
  auto it = std::lower_bound(poses.begin(), poses.end(), time_s,
                             [](const StampedPose& p, double t) { return p.time_s < t; });
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

JsonObject ErrorsJson(const PositionErrorAt& e) {
  JsonObject o;
  o.Add("height_error_m", e.height_error_m);
  o.Add("position_error_m", e.position_error_m);
  return o;
}

}  // namespace

JsonObject WriteMapOutputs(const std::filesystem::path& out_dir, const pipeline::Mapper& mapper,
                           const MapOutputOptions& options) {
  const std::vector<StampedPose> trajectory = mapper.OptimizedTrajectory();
  io::WriteTumTrajectory(out_dir / "trajectory.tum", trajectory);
  io::WriteKittiTrajectory(out_dir / "trajectory_kitti.txt", trajectory);

  const std::vector<Eigen::Vector3f> points = mapper.MapPoints(options.map_voxel_m);
  io::WritePcdXyz(out_dir / "map.pcd", points);
  io::WritePly(out_dir / "map.ply", points);
  octomap::OcTree tree(options.octree_resolution_m);
  for (const Eigen::Vector3f& p : points) tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  map::WriteOctomapBinary(out_dir / "map.bt", tree);
  WriteLoopClosures(out_dir / "loop_closures.csv", mapper.LoopClosureLinks());

  const pipeline::MapperStats s = mapper.stats();
  JsonObject o;
  o.Add("key_scans", s.key_scans);
  o.Add("submaps", static_cast<std::size_t>(s.submaps));
  o.Add("retired_submaps", s.retired_submaps);
  o.Add("loop_closures", s.loop_closures);
  o.Add("optimisations", s.optimisations);
  o.Add("optimisation_failures", s.optimisation_failures);
  o.Add("optimisation_s", s.optimisation_s);
  o.Add("key_scan_points", s.key_scan_points);
  o.Add("map_points_kept", s.map_points_kept);
  o.Add("loop_searches", s.loop_search.searches);
  o.Add("loop_candidates", s.loop_search.candidates);
  o.Add("loop_rejected", s.loop_search.rejected);
  o.Add("loop_matchers_built", s.loop_search.matchers_built);
  o.Add("map_points", points.size());
  o.Add("map_voxel_m", options.map_voxel_m);
  o.Add("messages", s.messages);
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

JsonObject LoopPointJson(const LoopPointErrors& errors) {
  JsonObject o;
  o.Add("time_s", errors.time_s);
  o.Add("odometry", ErrorsJson(errors.odometry));
  o.Add("optimized", ErrorsJson(errors.optimized));
  return o;
}

}  // namespace unimap::cli
