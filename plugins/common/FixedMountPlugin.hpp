#pragma once
#include <Eigen/Geometry>

#include "unimap/Extrinsic.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::payload {

// What every payload whose LiDAR is rigidly mounted on the body shares:
//   T_body_lidar(t) = T_body_lidar (extrinsic.body_lidar), no motor, no encoder.
// Subclasses add their sensor model (Name, Defaults, Configure, Deskew).
class FixedMountPlugin : public PayloadPlugin {
 public:
  // The parameter group of the mount.
  static constexpr const char* kBodyLidar = "extrinsic.body_lidar";

  // False: nothing moves the LiDAR relative to the body.
  bool UsesEncoder() const final;
  // 0 (no motor); the encoder is ignored.
  double MotorAngleAt(const EncoderTrack& encoder, double time_s) const final;
  // The constant T_body_lidar; the encoder and time are ignored.
  Eigen::Isometry3d BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const final;

 protected:
  // Adds extrinsic.body_lidar.* with defaults as their values.
  static void AddMountTo(const Extrinsic& defaults, ParameterSet* set);
  // Reads extrinsic.body_lidar.*; throws ConfigError (nothing changed then).
  static Extrinsic ReadMount(const ParameterMap& parameters);
  // Applies a mount read by ReadMount.
  void SetMount(const Extrinsic& body_lidar);
  // T_body_lidar as a function of time, for DeskewScan.
  MountQuery Mount() const;

 private:
  Extrinsic body_lidar_;                                            // extrinsic.body_lidar.*
  Eigen::Isometry3d T_body_lidar_ = Eigen::Isometry3d::Identity();  // body_lidar_ as a transform
};

}  // namespace unimap::payload
