#pragma once
#include <string>

#include <Eigen/Geometry>

#include "../common/MotorModel.hpp"
#include "LineScannerModel.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::payload {

// rotating_2d: a 2D line scanner (Hokuyo UTM-30LX class: 40 Hz, 270 deg,
// 1081 beams, 0.1..30 m) on a continuously turning motor (the paper's DJI
// M100 payload, 30 rpm). Default geometry: the motor turns about the body's
// vertical z axis and the scanner is rolled 90 deg on it (T_motor_lidar), so
// its scan plane is vertical, contains the motor axis and is centred on a
// horizontal direction; the plane sweeps the sphere as the motor turns.
// Every beam gets the motor angle at its own firing time:
//   T_body_lidar(t_i) = T_body_motor * Rot(axis, theta(t_i)) * T_motor_lidar.
class Rotating2dPlugin final : public PayloadPlugin {
 public:
  // Configured with Defaults().
  Rotating2dPlugin();

  // "rotating_2d".
  std::string Name() const override;
  std::string Description() const override;
  // CoreParameters (N = 40, ...) + lidar.* + motor.* + extrinsic.body_motor.*
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
  // Beam times from azimuth when the line has none, then rigid-body deskew
  // with the motor angle at every beam's time.
  BodyScan Deskew(const RawScan& scan, const EncoderTrack& encoder, const MotionQuery& T_world_body_at) const override;

 private:
  CoreParameters core_;     // the paper's parameters, as configured
  LineScannerModel lidar_;  // lidar.* keys
  MotorModel motor_;        // motor.* and extrinsic.* keys
};

}  // namespace unimap::payload
