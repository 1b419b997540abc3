#pragma once
#include <string>

#include <Eigen/Geometry>

#include "../common/MotorModel.hpp"
#include "../common/SpinningLidarModel.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::payload {

// rotating_3d: a VLP-16 on a continuously turning motor (the paper's DJI M600
// payload, 30 rpm). Default geometry: the motor turns about the body's
// vertical z axis and the VLP-16 lies on its side (T_motor_lidar: roll
// 90 deg), so its scan plane is vertical and contains the motor axis; half a
// motor revolution (1 s at 30 rpm) sweeps that plane over the whole sphere.
// Per point (motor angle from the encoder at the point's firing time):
//   T_body_lidar(t) = T_body_motor * Rot(axis, theta(t)) * T_motor_lidar.
class Rotating3dPlugin final : public PayloadPlugin {
 public:
  // Configured with Defaults().
  Rotating3dPlugin();

  // "rotating_3d".
  std::string Name() const override;
  std::string Description() const override;
  // CoreParameters (N = 10, ...) + lidar.* + motor.* + extrinsic.body_motor.*
  // + extrinsic.motor_lidar.*.
  ParameterSet Defaults() const override;
  // Validates against Defaults() and applies every key; on ConfigError the
  // previous configuration stays in effect.
  void Configure(const ParameterMap& parameters) override;
  // True: the motor angle comes from the encoder.
  bool UsesEncoder() const override;
  // theta(t) = direction * encoder(t) + offset; InputError outside coverage.
  double MotorAngleAt(const EncoderTrack& encoder, double time_s) const override;
  // T_body_lidar(theta(t)); InputError outside coverage.
  Eigen::Isometry3d BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const override;
  // Firing times from azimuth (in the LiDAR frame) when the scan has none,
  // then rigid-body deskew with the motor angle at every point's time.
  BodyScan Deskew(const RawScan& scan, const EncoderTrack& encoder, const MotionQuery& T_world_body_at) const override;

 private:
  CoreParameters core_;       // the paper's parameters, as configured
  SpinningLidarModel lidar_;  // lidar.* keys
  MotorModel motor_;          // motor.* and extrinsic.* keys
};

}  // namespace unimap::payload
