#include "Fixed3dPlugin.hpp"

#include "../common/CoreDefaults.hpp"
#include "unimap/PluginExport.hpp"

namespace unimap::payload {
namespace {

// The paper's parameters for a fixed VLP-16 (corridor-scale indoor mapping).
CoreDefaults FixedVlp16CoreDefaults() {
  CoreDefaults d;
  d.values.scans_per_3d_scan = 5;
  d.why_n = "5 sweeps (0.5 s): one sweep covers 360 x 30 deg, inserting every sweep costs a map update per 0.1 s";
  d.values.scans_3d_per_submap = 20;
  d.why_m = "2 s of sweeps per submap keeps its drift small while it is matched against";
  d.values.scans_3d_per_optimization = 10;
  d.why_i = "an optimisation every second of data";
  d.values.sigma_accel_m_s2 = 0.02;
  d.why_sigma_a = "a MEMS IMU sampled at 200 Hz";
  d.values.sigma_gyro_rad_s = 0.002;
  d.why_sigma_g = "a MEMS IMU sampled at 200 Hz";
  d.values.distance_map_resolution_m = 0.1;
  d.why_resolution = "corridors and rooms: 0.1 m keeps walls and door frames distinct";
  d.values.distance_map_max_range_m = 20.0;
  d.why_max_range = "a 40 m box covers what indoor sweeps see well";
  return d;
}

// The LiDAR 0.1 m above the body (IMU) origin, axes aligned.
Extrinsic DefaultBodyLidar() {
  Extrinsic e;
  e.translation_m = Eigen::Vector3d(0.0, 0.0, 0.1);
  return e;
}

}  // namespace

Fixed3dPlugin::Fixed3dPlugin() { Configure(Defaults().DefaultMap()); }

std::string Fixed3dPlugin::Name() const { return "fixed_3d"; }

std::string Fixed3dPlugin::Description() const {
  return "Spinning multi-beam 3D LiDAR (Velodyne VLP-16 class: 16 rings, -15..+15 deg, 10 Hz, "
         "0.4..100 m) fixed to the body; firing times from azimuth when a scan has none";
}

ParameterSet Fixed3dPlugin::Defaults() const {
  ParameterSet set;
  FixedVlp16CoreDefaults().AddTo(&set);
  SpinningLidarModel{}.AddTo(&set);  // a VLP-16
  AddMountTo(DefaultBodyLidar(), &set);
  return set;
}

void Fixed3dPlugin::Configure(const ParameterMap& parameters) {
  Defaults().Validate(parameters);
  // Read everything before changing anything: a ConfigError leaves *this as it was.
  const CoreParameters core = CoreParameters::FromMap(parameters);
  const SpinningLidarModel lidar = SpinningLidarModel::FromMap(parameters);
  const Extrinsic body_lidar = ReadMount(parameters);
  core_ = core;
  lidar_ = lidar;
  SetMount(body_lidar);
}

BodyScan Fixed3dPlugin::Deskew(const RawScan& scan, const EncoderTrack& /*encoder*/,
                               const MotionQuery& T_world_body_at) const {
  return lidar_.Deskew(scan, Mount(), T_world_body_at);
}

}  // namespace unimap::payload

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap::payload::Fixed3dPlugin)
