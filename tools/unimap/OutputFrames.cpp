#include "OutputFrames.hpp"

#include <system_error>
#include <utility>
#include <vector>

namespace unimap::cli {

Json OutputFramesJson(const std::filesystem::path& out_dir, bool prior_map) {
  const std::string map = prior_map ? "the map frame: the prior map's (--map)"
                                    : "the map frame: the body's position and heading at the first pose, z against "
                                      "gravity with an IMU (else the body's z)";
  const std::vector<std::pair<const char*, std::string>> files = {
      {"trajectory.tum",
       "T_map_body per scan (TUM: time x y z qx qy qz qw): the body frame (the one the platform's extrinsics are given "
       "in) in " +
           map + (prior_map ? "" : "; optimised by the pose graph")},
      {"trajectory_odometry.tum",
       "T_local_body per scan (TUM): the body frame in the odometry (local) frame, the filter's estimate before "
       "pose-graph optimisation; the local frame is the map frame until the first optimisation"},
      {"trajectory_kitti.txt",
       "T_map_body per scan as 3x4 row-major matrices (KITTI layout, no times): the body "
       "frame in " +
           map},
      {"trajectory_kitti_camera.txt",
       "T_cam0_cam per scan (KITTI layout): KITTI's left camera relative to its first pose, "
       "Tr * T_lidar0_lidar * Tr^-1 with the dataset's camera_from_lidar (the frame of KITTI's poses)"},
      {"map.pcd", "points in " + map},
      {"map.ply", "points in " + map},
      {"map.bt", "OctoMap occupancy in " + map},
      {"groundtruth.tum", "the recording's ground truth as it gives it (TUM), read directly from the recording"},
  };
  Json frames = Json::object();
  std::error_code ec;
  for (const auto& [file, text] : files) {
    if (std::filesystem::exists(out_dir / file, ec)) frames[file] = text;
  }
  return frames;
}

}  // namespace unimap::cli
