#pragma once
// Shared fixtures of the simulator tests: a box room and its analytic ranges,
// a motor mount turning at a constant rate.
#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Geometry>

#include "BoxPrimitive.hpp"
#include "World.hpp"

namespace unimap::sim::test {

// An axis-aligned box room seen from inside.
struct BoxRoom {
  Eigen::Vector3d center = Eigen::Vector3d(1.0, 0.0, 1.5);
  Eigen::Vector3d size = Eigen::Vector3d(10.0, 6.0, 4.0);

  World MakeWorld() const {
    World world;
    world.Add(std::make_unique<BoxPrimitive>(center, size));
    world.Build();
    return world;
  }
  // Distance from p (inside) along unit d to the first wall.
  double RangeFrom(const Eigen::Vector3d& p, const Eigen::Vector3d& d) const {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) {
      if (d[j] == 0.0) continue;
      const double wall = center[j] + (d[j] > 0.0 ? 0.5 : -0.5) * size[j];
      best = std::min(best, (wall - p[j]) / d[j]);
    }
    return best;
  }
};

// T_body_lidar(t) = T_body_motor * Rz(rate t) * T_motor_lidar with the LiDAR
// rolled 90 deg and off the axis (its origin circles the motor axis).
inline Eigen::Isometry3d RotatingMount(double t, double rate_rad_s = M_PI) {
  Eigen::Isometry3d T_body_motor = Eigen::Isometry3d::Identity();
  T_body_motor.translation() = Eigen::Vector3d(0.0, 0.0, -0.1);
  Eigen::Isometry3d T_motor_lidar = Eigen::Isometry3d::Identity();
  T_motor_lidar.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  T_motor_lidar.translation() = Eigen::Vector3d(0.03, 0.0, -0.05);
  Eigen::Isometry3d R = Eigen::Isometry3d::Identity();
  R.linear() = Eigen::AngleAxisd(rate_rad_s * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T_body_motor * R * T_motor_lidar;
}

// A body pose at rest, yawed and slightly tilted.
inline Eigen::Isometry3d RestingBody() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.5, 0.3, 1.2);
  return T;
}

// A body moving at 1 m/s along x while turning at 0.5 rad/s.
inline Eigen::Isometry3d MovingBody(double t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.5 * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(-2.0 + t, 0.3, 1.2 + 0.1 * t);
  return T;
}

}  // namespace unimap::sim::test
