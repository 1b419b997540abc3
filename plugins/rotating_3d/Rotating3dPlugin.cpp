#include "Rotating3dPlugin.hpp"

#include "../common/CoreDefaults.hpp"
#include "unimap/PluginExport.hpp"

namespace unimap::payload {
namespace {

// The paper's parameters for a rotating VLP-16 (the 40 m patio).
CoreDefaults RotatingVlp16CoreDefaults() {
  CoreDefaults d;
  d.values.scans_per_3d_scan = 10;
  d.why_n = "10 sweeps at 10 Hz = 1 s = half a motor revolution at 30 rpm: the full sphere";
  d.values.scans_3d_per_submap = 20;
  d.why_m = "20 s of full-sphere scans per submap";
  d.values.scans_3d_per_optimization = 10;
  d.why_i = "an optimisation every 10 s of data";
  d.values.sigma_accel_m_s2 = 0.02;
  d.why_sigma_a = "a MEMS IMU sampled at 200 Hz";
  d.values.sigma_gyro_rad_s = 0.002;
  d.why_sigma_g = "a MEMS IMU sampled at 200 Hz";
  d.values.distance_map_resolution_m = 0.3;
  d.why_resolution = "open outdoor scenes (paper: 0.3 m on the patio)";
  d.values.distance_map_max_range_m = 20.0;
  d.why_max_range = "the paper's 40 m x 40 m x 40 m box";
  return d;
}

// Motor 0.15 m below the body origin turning about body z at 30 rpm; the
// VLP-16 rolled 90 deg on it (its spin axis horizontal, along motor -y at
// theta = 0), 0.1 m further down.
MotorModel VerticalMotor() {
  MotorModel motor;
  motor.mount.body_motor.translation_m = Eigen::Vector3d(0.0, 0.0, -0.15);
  motor.mount.motor_lidar.translation_m = Eigen::Vector3d(0.0, 0.0, -0.1);
  motor.mount.motor_lidar.rpy_deg = Eigen::Vector3d(90.0, 0.0, 0.0);
  motor.mount.axis_motor = Eigen::Vector3d::UnitZ();
  motor.mount.encoder_offset_deg = 0.0;
  motor.mount.encoder_direction = 1;
  motor.rate_rpm = 30.0;
  return motor;
}

}  // namespace

Rotating3dPlugin::Rotating3dPlugin() { Configure(Defaults().DefaultMap()); }

std::string Rotating3dPlugin::Name() const { return "rotating_3d"; }

std::string Rotating3dPlugin::Description() const {
  return "VLP-16 class 3D LiDAR on its side on a motor turning about body z (30 rpm, encoder "
         "synchronised per point): the vertical scan plane sweeps the full sphere every half "
         "revolution";
}

ParameterSet Rotating3dPlugin::Defaults() const {
  ParameterSet set;
  RotatingVlp16CoreDefaults().AddTo(&set);
  SpinningLidarModel{}.AddTo(&set);  // a VLP-16
  VerticalMotor().AddTo(&set);
  return set;
}

void Rotating3dPlugin::Configure(const ParameterMap& parameters) {
  Defaults().Validate(parameters);
  // Read everything before changing anything: a ConfigError leaves *this as it was.
  const CoreParameters core = CoreParameters::FromMap(parameters);
  const SpinningLidarModel lidar = SpinningLidarModel::FromMap(parameters);
  const MotorModel motor = MotorModel::FromMap(parameters);
  core_ = core;
  lidar_ = lidar;
  motor_ = motor;
}

bool Rotating3dPlugin::UsesEncoder() const { return true; }

double Rotating3dPlugin::MotorAngleAt(const EncoderTrack& encoder, double time_s) const {
  return motor_.MotorAngleAt(encoder, time_s);
}

Eigen::Isometry3d Rotating3dPlugin::BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const {
  return motor_.BodyFromLidarAt(encoder, time_s);
}

BodyScan Rotating3dPlugin::Deskew(const RawScan& scan, const EncoderTrack& encoder,
                                  const MotionQuery& T_world_body_at) const {
  return lidar_.Deskew(
      scan, [this, &encoder](double time_s) { return motor_.BodyFromLidarAt(encoder, time_s); }, T_world_body_at);
}

}  // namespace unimap::payload

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap::payload::Rotating3dPlugin)
