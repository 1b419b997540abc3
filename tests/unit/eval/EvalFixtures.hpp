#pragma once
// Hand-built trajectories with exactly known geometry for the eval tests.
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/StampedPose.hpp"

namespace unimap::eval::testing {

// A pose from position and roll-pitch-yaw (R = Rz(yaw) Ry(pitch) Rx(roll)).
inline StampedPose MakePose(double time_s, const Eigen::Vector3d& p, double roll = 0.0, double pitch = 0.0,
                            double yaw = 0.0) {
  StampedPose pose;
  pose.time_s = time_s;
  pose.T_map_body.translation() = p;
  pose.T_map_body.linear() =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return pose;
}

// n + 1 poses along +x, 1 m and 1 s apart (x = k, t = k), identity rotation.
inline std::vector<StampedPose> StraightLine(int n) {
  std::vector<StampedPose> poses;
  for (int k = 0; k <= n; ++k) poses.push_back(MakePose(k, Eigen::Vector3d(k, 0.0, 0.0)));
  return poses;
}

// A climbing circle (radius 10 m, one turn, 2 m climb) at 10 Hz over 60 s,
// heading along the tangent with a small roll and pitch wobble: no two
// positions or rotations alike, nothing degenerate.
inline std::vector<StampedPose> Helix() {
  std::vector<StampedPose> poses;
  for (int k = 0; k <= 600; ++k) {
    const double t = 0.1 * k;
    const double theta = 2.0 * M_PI * t / 60.0;
    poses.push_back(MakePose(100.0 + t, Eigen::Vector3d(10.0 * std::cos(theta), 10.0 * std::sin(theta), 2.0 * t / 60.0),
                             0.05 * std::sin(0.7 * t), 0.03 * std::cos(0.4 * t), theta + M_PI / 2.0));
  }
  return poses;
}

// poses with every T_map_body replaced by T_new_old * T_map_body.
inline std::vector<StampedPose> Transformed(std::vector<StampedPose> poses, const Eigen::Isometry3d& T_new_old) {
  for (StampedPose& p : poses) p.T_map_body = T_new_old * p.T_map_body;
  return poses;
}

}  // namespace unimap::eval::testing
