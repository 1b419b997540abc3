#pragma once
#include <Eigen/Geometry>

#include "unimap/EncoderTrack.hpp"
#include "unimap/MotorMount.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap::payload {

// A LiDAR on a motor read by an encoder: the SDK's MotorMount geometry plus
// the nominal motor rate. Shared by rotating_3d and rotating_2d, which differ
// only in defaults and in the LiDAR on the motor.
struct MotorModel {
  MotorMount mount;        // T_body_lidar(theta) = T_body_motor * Rot(axis, theta) * T_motor_lidar
  double rate_rpm = 30.0;  // nominal speed (rev/min); informative: the encoder rules

  // Adds MotorMount's keys ("extrinsic.body_motor.*", "extrinsic.motor_lidar.*",
  // "motor.axis", "motor.encoder_offset_deg", "motor.encoder_direction") and
  // "motor.rate_rpm", with this object's values as defaults.
  void AddTo(ParameterSet* set) const;
  // Reads those keys; throws ConfigError.
  static MotorModel FromMap(const ParameterMap& map);

  // theta(t) = direction * encoder(t) + offset, encoder(t) interpolated by the
  // track; throws InputError outside encoder coverage or in a gap.
  double MotorAngleAt(const EncoderTrack& encoder, double time_s) const;
  // T_body_lidar(theta(t)); throws like MotorAngleAt.
  Eigen::Isometry3d BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const;
};

}  // namespace unimap::payload
