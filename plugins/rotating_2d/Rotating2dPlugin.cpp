#include "Rotating2dPlugin.hpp"

#include "../common/CoreDefaults.hpp"
#include "unimap/PluginExport.hpp"

namespace unimap::payload {
namespace {

// The paper's parameters for a rotating Hokuyo (tunnel and hallway scale).
CoreDefaults RotatingHokuyoCoreDefaults() {
  CoreDefaults d;
  d.values.scans_per_3d_scan = 40;
  d.why_n = "40 lines at 40 Hz = 1 s = half a motor revolution at 30 rpm: the full sphere";
  d.values.scans_3d_per_submap = 20;
  d.why_m = "20 s of full-sphere scans per submap";
  d.values.scans_3d_per_optimization = 10;
  d.why_i = "an optimisation every 10 s of data";
  d.values.sigma_accel_m_s2 = 0.02;
  d.why_sigma_a = "a MEMS IMU sampled at 200 Hz";
  d.values.sigma_gyro_rad_s = 0.002;
  d.why_sigma_g = "a MEMS IMU sampled at 200 Hz";
  d.values.distance_map_resolution_m = 0.1;
  d.why_resolution = "narrow hallways and tunnels: 0.1 m resolves a 1.1 m-wide corridor";
  d.values.distance_map_max_range_m = 30.0;
  d.why_max_range =
      "the scanner's 30 m range: a line holds few returns, and the far ones (a corridor's or a tunnel's end "
      "walls) are what hold its long axis";
  return d;
}

// Motor 0.1 m below the body origin turning about body z at 30 rpm; the
// scanner rolled 90 deg on it (scan plane = motor x-z plane at theta = 0,
// beams centred on motor +x), 0.05 m further down.
MotorModel VerticalMotor() {
  MotorModel motor;
  motor.mount.body_motor.translation_m = Eigen::Vector3d(0.0, 0.0, -0.1);
  motor.mount.motor_lidar.translation_m = Eigen::Vector3d(0.0, 0.0, -0.05);
  motor.mount.motor_lidar.rpy_deg = Eigen::Vector3d(90.0, 0.0, 0.0);
  motor.mount.axis_motor = Eigen::Vector3d::UnitZ();
  motor.mount.encoder_offset_deg = 0.0;
  motor.mount.encoder_direction = 1;
  motor.rate_rpm = 30.0;
  return motor;
}

}  // namespace

Rotating2dPlugin::Rotating2dPlugin() { Configure(Defaults().DefaultMap()); }

std::string Rotating2dPlugin::Name() const { return "rotating_2d"; }

std::string Rotating2dPlugin::Description() const {
  return "2D line scanner (Hokuyo UTM-30LX class: 40 Hz, 270 deg, 1081 beams, 0.1..30 m) rolled "
         "90 deg on a motor turning about body z (30 rpm), encoder synchronised per beam";
}

ParameterSet Rotating2dPlugin::Defaults() const {
  ParameterSet set;
  RotatingHokuyoCoreDefaults().AddTo(&set);
  LineScannerModel{}.AddTo(&set);  // a UTM-30LX
  VerticalMotor().AddTo(&set);
  return set;
}

void Rotating2dPlugin::Configure(const ParameterMap& parameters) {
  Defaults().Validate(parameters);
  // Read everything before changing anything: a ConfigError leaves *this as it was.
  const CoreParameters core = CoreParameters::FromMap(parameters);
  const LineScannerModel lidar = LineScannerModel::FromMap(parameters);
  const MotorModel motor = MotorModel::FromMap(parameters);
  core_ = core;
  lidar_ = lidar;
  motor_ = motor;
}

bool Rotating2dPlugin::UsesEncoder() const { return true; }

double Rotating2dPlugin::MotorAngleAt(const EncoderTrack& encoder, double time_s) const {
  return motor_.MotorAngleAt(encoder, time_s);
}

Eigen::Isometry3d Rotating2dPlugin::BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const {
  return motor_.BodyFromLidarAt(encoder, time_s);
}

BodyScan Rotating2dPlugin::Deskew(const RawScan& scan, const EncoderTrack& encoder,
                                  const MotionQuery& T_world_body_at) const {
  return lidar_.Deskew(
      scan, [this, &encoder](double time_s) { return motor_.BodyFromLidarAt(encoder, time_s); }, T_world_body_at);
}

}  // namespace unimap::payload

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap::payload::Rotating2dPlugin)
