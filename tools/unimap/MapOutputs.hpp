#pragma once
// The mapping outputs of `unimap run`: the optimised trajectory (TUM and
// KITTI), the map (PCD, PLY, OctoMap) and the mapper's counts for run.json.
#include <filesystem>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "Json.hpp"
#include "pipeline/Mapper.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::cli {

// Settings of the written map.
struct MapOutputOptions {
  double map_voxel_m = 0.1;          // map.pcd / map.ply keep one point per voxel of this edge (m)
  double octree_resolution_m = 0.1;  // voxel edge of map.bt (m)
  // KITTI data (DatasetMetadata::camera_from_lidar): also trajectory_kitti_camera.txt,
  // the poses of KITTI's left camera relative to its first, T_cam0_cam = Tr T_lidar0_lidar Tr^-1,
  // as KITTI's devkit and evo read them; T_body_lidar is the payload's (fixed) mount.
  std::optional<Eigen::Isometry3d> T_cam_lidar;
  Eigen::Isometry3d T_body_lidar = Eigen::Isometry3d::Identity();
};

// Writes out_dir/trajectory.tum and trajectory_kitti.txt (the optimised
// trajectory, body frame; with options.T_cam_lidar also trajectory_kitti_camera.txt), map.pcd, map.ply, map.bt and
// loop_closures.csv (each accepted closure: time, the 3D scan's position, the matched submap's origin), each
// atomically; returns the mapper's counts and the file names as run.json's "mapping" object. Throws unimap::Error when
// a file cannot be written.
Json WriteMapOutputs(const std::filesystem::path& out_dir, const pipeline::Mapper& mapper,
                     const MapOutputOptions& options);

// Position error of one pose against the truth at the same time.
struct PositionErrorAt {
  double height_error_m = 0.0;    // |dz|
  double position_error_m = 0.0;  // |d|
};

// The errors at the first loop closure (issue 5: "height error at the loop
// point, before and after"), start-anchored on the first odometry pose's
// position and heading (eval::AnchorTransform, as drift_percent).
struct LoopPointErrors {
  double time_s = 0.0;        // the first loop closure's 3D scan
  PositionErrorAt odometry;   // the filter's estimate, before optimisation
  PositionErrorAt optimized;  // the optimised trajectory
};

// LoopPointErrors at time_s of the odometry and optimised trajectories
// against the truth; nullopt when a trajectory has no pose within 0.1 s of
// time_s (or the truth none at the odometry's start).
std::optional<LoopPointErrors> ComputeLoopPointErrors(const std::vector<StampedPose>& odometry,
                                                      const std::vector<StampedPose>& optimized,
                                                      const std::vector<StampedPose>& truth, double time_s);

// run.json's "loop_point": {"time_s", "odometry": {...}, "optimized": {...}},
// each with "height_error_m" and "position_error_m".
Json LoopPointJson(const LoopPointErrors& errors);

}  // namespace unimap::cli
