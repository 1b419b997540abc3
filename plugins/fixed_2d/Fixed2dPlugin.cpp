#include "Fixed2dPlugin.hpp"

#include "../common/CoreDefaults.hpp"
#include "unimap/PluginExport.hpp"

namespace unimap::payload {
namespace {

// The paper's parameters for a fixed planar scanner on a ground robot.
CoreDefaults FixedPlanarCoreDefaults() {
  CoreDefaults d;
  d.values.scans_per_3d_scan = 5;
  d.why_n = "5 lines per map insertion: a plane says little alone, a few lines add the robot's motion";
  d.values.scans_3d_per_submap = 20;
  d.why_m = "100 lines per submap keeps its drift small while it is matched against";
  d.values.scans_3d_per_optimization = 10;
  d.why_i = "an optimisation every 50 lines";
  d.values.sigma_accel_m_s2 = 0.02;
  d.why_sigma_a = "a MEMS IMU sampled at 200 Hz (when the robot has one)";
  d.values.sigma_gyro_rad_s = 0.002;
  d.why_sigma_g = "a MEMS IMU sampled at 200 Hz (when the robot has one)";
  d.values.distance_map_resolution_m = 0.1;
  d.why_resolution = "corridors and offices: 0.1 m keeps walls and door frames distinct";
  d.values.distance_map_max_range_m = 20.0;
  d.why_max_range = "a 40 m box covers what a planar scanner sees well indoors";
  return d;
}

// A SICK LMS 200 class scanner: 180 deg in 181 beams, 75 Hz mirror, 0.1..80 m.
LineScannerModel PlanarScanner() {
  LineScannerModel lidar;
  lidar.scan_rate_hz = 75.0;
  lidar.fov_deg = 180.0;
  lidar.beams = 181;
  lidar.limits = RangeLimits{0.1, 80.0};
  return lidar;
}

// The scanner 0.3 m above the body origin, scan plane = body x-y plane.
Extrinsic DefaultBodyLidar() {
  Extrinsic e;
  e.translation_m = Eigen::Vector3d(0.0, 0.0, 0.3);
  return e;
}

}  // namespace

Fixed2dPlugin::Fixed2dPlugin() { Configure(Defaults().DefaultMap()); }

std::string Fixed2dPlugin::Name() const { return "fixed_2d"; }

std::string Fixed2dPlugin::Description() const {
  return "2D line scanner (SICK LMS 200 class: 180 deg, 181 beams, 75 Hz, 0.1..80 m) fixed to the body, "
         "scan plane = body x-y; beam times from azimuth when a line has none";
}

ParameterSet Fixed2dPlugin::Defaults() const {
  ParameterSet set;
  FixedPlanarCoreDefaults().AddTo(&set);
  PlanarScanner().AddTo(&set);
  AddMountTo(DefaultBodyLidar(), &set);
  return set;
}

void Fixed2dPlugin::Configure(const ParameterMap& parameters) {
  Defaults().Validate(parameters);
  // Read everything before changing anything: a ConfigError leaves *this as it was.
  const CoreParameters core = CoreParameters::FromMap(parameters);
  const LineScannerModel lidar = LineScannerModel::FromMap(parameters);
  const Extrinsic body_lidar = ReadMount(parameters);
  core_ = core;
  lidar_ = lidar;
  SetMount(body_lidar);
}

BodyScan Fixed2dPlugin::Deskew(const RawScan& scan, const EncoderTrack& /*encoder*/,
                               const MotionQuery& T_world_body_at) const {
  return lidar_.Deskew(scan, Mount(), T_world_body_at);
}

}  // namespace unimap::payload

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap::payload::Fixed2dPlugin)
