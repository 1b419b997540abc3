#pragma once
#include <Eigen/Geometry>

#include "unimap/Export.hpp"
#include "unimap/Extrinsic.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap {

// A LiDAR on a motor (spinning or nodding). With motor angle
// theta = direction * encoder_angle + offset:
//   T_body_lidar(theta) = T_body_motor * Rot(axis_motor, theta) * T_motor_lidar.
// Shared by every motor payload; plugins differ only in defaults.
struct UNIMAP_SDK_API MotorMount {
  Extrinsic body_motor;                                   // T_body_motor
  Extrinsic motor_lidar;                                  // T_motor_lidar at theta = 0
  Eigen::Vector3d axis_motor = Eigen::Vector3d::UnitZ();  // rotation axis, motor frame (normalised on use)
  double encoder_offset_deg = 0.0;                        // motor angle at encoder reading 0
  int encoder_direction = 1;                              // +1: encoder counts with the axis, -1: against

  // Motor angle (rad) for an unwrapped encoder reading (rad).
  double MotorAngle(double encoder_angle_rad) const;
  // T_body_lidar at a motor angle (rad).
  Eigen::Isometry3d BodyFromLidar(double motor_angle_rad) const;

  // Adds the keys "extrinsic.body_motor.*", "extrinsic.motor_lidar.*",
  // "motor.axis", "motor.encoder_offset_deg", "motor.encoder_direction".
  void AddTo(ParameterSet* set) const;
  // Reads those keys; throws ConfigError (zero axis, direction not +-1).
  static MotorMount FromMap(const ParameterMap& map);
};

}  // namespace unimap
