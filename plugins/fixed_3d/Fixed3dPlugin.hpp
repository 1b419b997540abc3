#pragma once
#include <string>

#include <Eigen/Geometry>

#include "../common/FixedMountPlugin.hpp"
#include "../common/SpinningLidarModel.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::payload {

// fixed_3d: a spinning multi-beam LiDAR (Velodyne VLP-16 class: 16 rings,
// -15..+15 deg, 10 Hz, 0.4..100 m) rigidly mounted on the body:
//   T_body_lidar(t) = T_body_lidar (extrinsic.body_lidar), no motor, no encoder.
class Fixed3dPlugin final : public FixedMountPlugin {
 public:
  // Configured with Defaults().
  Fixed3dPlugin();

  // "fixed_3d".
  std::string Name() const override;
  std::string Description() const override;
  // CoreParameters (N = 1, ...) + lidar.* + extrinsic.body_lidar.*.
  ParameterSet Defaults() const override;
  // Validates against Defaults() and applies every key; on ConfigError the
  // previous configuration stays in effect.
  void Configure(const ParameterMap& parameters) override;
  // Firing times from azimuth when the scan has none, then rigid-body deskew.
  BodyScan Deskew(const RawScan& scan, const EncoderTrack& encoder, const MotionQuery& T_world_body_at) const override;

 private:
  CoreParameters core_;       // the paper's parameters, as configured
  SpinningLidarModel lidar_;  // lidar.* keys
};

}  // namespace unimap::payload
