#include "FixedMountPlugin.hpp"

namespace unimap::payload {

bool FixedMountPlugin::UsesEncoder() const { return false; }

double FixedMountPlugin::MotorAngleAt(const EncoderTrack& /*encoder*/, double /*time_s*/) const { return 0.0; }

Eigen::Isometry3d FixedMountPlugin::BodyFromLidarAt(const EncoderTrack& /*encoder*/, double /*time_s*/) const {
  return T_body_lidar_;
}

void FixedMountPlugin::AddMountTo(const Extrinsic& defaults, ParameterSet* set) {
  defaults.AddTo(set, kBodyLidar, "LiDAR frame in the body frame (T_body_lidar)");
}

Extrinsic FixedMountPlugin::ReadMount(const ParameterMap& parameters) {
  return Extrinsic::FromMap(parameters, kBodyLidar);
}

void FixedMountPlugin::SetMount(const Extrinsic& body_lidar) {
  body_lidar_ = body_lidar;
  T_body_lidar_ = body_lidar.ToIsometry();
}

MountQuery FixedMountPlugin::Mount() const {
  const Eigen::Isometry3d T_body_lidar = T_body_lidar_;
  return [T_body_lidar](double /*time_s*/) { return T_body_lidar; };
}

}  // namespace unimap::payload
