#pragma once
#include <string>

#include <Eigen/Geometry>

#include "../common/FixedMountPlugin.hpp"
#include "../rotating_2d/LineScannerModel.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::payload {

// fixed_2d: a 2D line scanner rigidly mounted on the body (SICK LMS 200
// class: 180 deg, 181 beams, 75 Hz mirror, 0.1..80 m; the planar robots of
// CARMEN logs), scan plane = the body's x-y plane by default:
//   T_body_lidar(t) = T_body_lidar (extrinsic.body_lidar), no motor, no encoder.
// A single plane observes x, y and yaw only: map it with planar matching
// (`mapper: {gpf: {planar: true}}` in the platform file) and a planar
// motion source (wheel odometry).
class Fixed2dPlugin final : public FixedMountPlugin {
 public:
  // Configured with Defaults().
  Fixed2dPlugin();

  // "fixed_2d".
  std::string Name() const override;
  std::string Description() const override;
  // CoreParameters + lidar.* (LineScannerModel) + extrinsic.body_lidar.*.
  ParameterSet Defaults() const override;
  // Validates against Defaults() and applies every key; on ConfigError the
  // previous configuration stays in effect.
  void Configure(const ParameterMap& parameters) override;
  // Beam times from azimuth when the line has none, then rigid-body deskew.
  BodyScan Deskew(const RawScan& scan, const EncoderTrack& encoder, const MotionQuery& T_world_body_at) const override;

 private:
  CoreParameters core_;     // the paper's parameters, as configured
  LineScannerModel lidar_;  // lidar.* keys
};

}  // namespace unimap::payload
