#include "pipeline/LocalizerOptions.hpp"

#include <algorithm>


namespace unimap::pipeline {

bool LocalizerOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  std::string inner;
  if (!eskf.IsValid(&inner)) {
    *why = "eskf: " + inner;
    return false;
  }
  if (!gpf.IsValid(&inner)) {
    *why = "gpf: " + inner;
    return false;
  }
  if (!map.IsValid(&inner)) {
    *why = "map: " + inner;
    return false;
  }
  if (!motion.IsValid(why)) return false;
  if (!reacquire.IsValid(&inner)) {
    *why = "reacquire: " + inner;
    return false;
  }
  if (neighbourhood_planes) {
    if (!neighbourhood_planes->IsValid(&inner)) {
      *why = "neighbourhood_plane: " + inner;
      return false;
    }
    if (!gpf.point_to_plane) {
      *why = "neighbourhood_planes needs gpf.point_to_plane";
      return false;
    }
  }
  if (line_gap_fill && !line_gap_fill->IsValid(&inner)) {
    *why = "line_gap_fill: " + inner;
    return false;
  }
  if (!(sweep_gate_sigmas >= 0.0)) {
    *why = "sweep_gate_sigmas must be >= 0";
    return false;
  }
  if (!(max_predicted_distance_m >= 0.0)) {
    *why = "max_predicted_distance_m must be >= 0";
    return false;
  }
  if (scans_per_3d_scan < 1 || !(static_init_s >= 0.0) || min_points_to_match < 1 ||
      !(max_scan_latency_s > 0.0) || !(max_initial_accel_bias_m_s2 > 0.0)) {
    *why = "scans_per_3d_scan and min_points_to_match must be >= 1, static_init_s >= 0, "
           "max_scan_latency_s and max_initial_accel_bias_m_s2 > 0";
    return false;
  }
  return true;
}

void LocalizerOptions::VisitFields(options::FieldVisitor& v) {
  v.Section("eskf", [&] { eskf.VisitFields(v); });
  v.Section("motion", [&] { motion.VisitFields(v); });
  v.Section("gpf", [&] { gpf.VisitFields(v); });
  v.Section("map", [&] { map.VisitFields(v); });
  v.Section("reacquire", [&] { reacquire.VisitFields(v); });
  v.Section("line_gap_fill", [&] {
    // Off is an unset optional; its fields keep their defaults meanwhile.
    bool enabled = line_gap_fill.has_value();
    map::LineGapFillOptions fill = line_gap_fill.value_or(map::LineGapFillOptions{});
    v.Field("enabled", &enabled, "");
    fill.VisitFields(v);
    if (enabled) {
      line_gap_fill = fill;
    } else {
      line_gap_fill.reset();
    }
  });
  v.SetElsewhere("scans_per_3d_scan", "the platform parameter scans_per_3d_scan");
  v.Field("static_init_s", &static_init_s, "s");
  v.Field("max_initial_accel_bias_m_s2", &max_initial_accel_bias_m_s2, "m/s^2");
  v.Field("min_points_to_match", &min_points_to_match, "count");
  v.Field("max_predicted_distance_m", &max_predicted_distance_m, "m");
  v.Field("sweep_gate_sigmas", &sweep_gate_sigmas, "");
  v.Field("max_scan_latency_s", &max_scan_latency_s, "s");
  v.Field("trilinear_distance", &trilinear_distance, "");
}

LocalizerOptions LocalizerOptions::FromPlatform(const CoreParameters& core) {
  LocalizerOptions o;
  o.scans_per_3d_scan = core.scans_per_3d_scan;
  o.eskf.sigma_accel_m_s2 = core.sigma_accel_m_s2;
  o.eskf.sigma_gyro_rad_s = core.sigma_gyro_rad_s;
  o.map.resolution_m = core.distance_map_resolution_m;
  o.map.max_range_m = core.distance_map_max_range_m;
  o.gpf.voxel_size_m = core.distance_map_resolution_m;
  // Distances to the surface inside each voxel, as magnitudes, instead of
  // to voxel centres (up to half a voxel off the surface). In the hallway at
  // 31.7 rpm the voxel-centre estimate kept a 0.5 deg pitch error from its
  // start, which leaked gravity into the travel direction until it ran
  // backwards. Signed distances (negative behind a surface) turned the
  // tunnel's heading (yaw error 0.87 deg). Measured with the line gate
  // below, ATE voxel centres -> unsigned surfaces: tunnel 0.316 -> 0.065 m
  // (map error 0.047 -> 0.016 m), hallway seeds 4 / 5 / 6 0.077 / 0.125 /
  // 0.141 -> 0.102 / 0.117 / 0.063 m, hallway at 31.7 rpm diverged ->
  // 0.098 m; corridor (fixed VLP-16, no gate) 0.072 -> 0.018 m, patio
  // (rotating VLP-16) 0.083 -> 0.080 m.
  o.map.subvoxel_surfaces = true;
  o.map.signed_surfaces = false;
  // Line scans: points farther than 1.5 voxels from the map at the
  // predicted pose are not measured. A line reaches past what the map
  // holds (the frontier ahead, the far walls between the stripes earlier
  // lines left), and measured against the nearest surface the map does hold
  // such points pull the pose back: hallway ATE, seeds 4 / 5 / 6, without
  // the gate 0.382 / 0.488 / 0.245 m. An error larger than the gate cannot
  // be corrected by the points it leaves out: at 1 voxel the tunnel slipped
  // 3.5 m while hovering (ATE 1.46 m; hallway 0.075 / 0.093 / 0.050 m).
  // 3D sweeps use the same gate widened by sweep_gate_sigmas of the
  // prediction (ScanMatcher), so an uncertain prediction keeps its points
  // (docs/robustness.md: tunnel, fixed VLP-16, ATE 2.23 -> 1.32 m).
  o.max_predicted_distance_m = 1.5 * core.distance_map_resolution_m;
  // Gauss-Newton refinement of every GPF match (PoseRefiner): the plain
  // GPF's Monte-Carlo noise (ESS near K when the tempered likelihood is
  // flatter than the prediction) made the hallway (rotating Hokuyo) diverge
  // while static; odometry ATE with 5 steps: hallway diverged -> 0.84 m,
  // patio 0.22 -> 0.08 m, corridor 0.58 -> 0.20 m, tunnel 0.58 -> 0.54 m.
  o.gpf.refine_iterations = 5;
  // The distance map is exact up to the particle filter's clamp (0.5 m, or
  // one voxel if coarser) and reads that beyond: the likelihood and the
  // refinement clamp there, and each metre of exact distance costs EDT
  // propagation around every new surface and memory (1.0 m before; speed,
  // memory and accuracy of both in docs/mapping.md, "Distance map clamp").
  o.ClampFieldAtLikelihood();
  // Every match is refined by Gauss-Newton, so the particles only place its
  // start, which 100 do at a fifth of the time of 500 (docs/design.md 1.3).
  o.gpf.num_particles = 100;
  return o;
}

void LocalizerOptions::ClampFieldAtLikelihood() {
  map.clamp_distance_m = std::max(gpf.clamp_distance_m, map.resolution_m);
}

void LocalizerOptions::UsePlaneMatching() {
  neighbourhood_planes = map::NeighbourhoodPlaneOptions{};
  gpf.point_to_plane = true;
  gpf.planes_only = true;
  // Planes are fitted across the measured stripes; with the gaps filled
  // (in a trial build that also put the filled points into the key scans)
  // hallway seed 6 went from ATE 0.049 to 0.157 m and the tunnel from 0.89
  // to 2.08 m.
  line_gap_fill.reset();
}

LocalizerOptions LocalizerOptions::ForPriorMap(const CoreParameters& core) {
  LocalizerOptions o = FromPlatform(core);
  o.localize_only = true;
  // A fixed map: distances to the surface inside each voxel, signed (20 s
  // tunnel, rotating Hokuyo: position RMSE 0.014 m vs 0.062 m to voxel
  // centres). The map is complete: every line point is measured.
  o.map.subvoxel_surfaces = true;
  o.map.signed_surfaces = true;
  o.max_predicted_distance_m = 0.0;
  // The field is computed once, not grown, so the coarse grid a payload maps
  // with for speed (rotating VLP-16: 0.3 m, the paper's patio value) is not
  // needed. Full 912 s tunnel flight, rotating VLP-16 in its true map: at
  // 0.3 m the estimate slips along the tunnel by a car's length at 840 s
  // (position RMSE 7.9 m); at 0.1 m, 0.019 m.
  o.map.resolution_m = std::min(o.map.resolution_m, kPriorMapResolutionM);
  o.gpf.voxel_size_m = o.map.resolution_m;
  // The field is computed once: the default clamp (unimap localize clamps a
  // .pcd map's field at the particle filter's clamp itself; a .bt map's
  // resolution is the file's and may be coarser).
  o.map.clamp_distance_m = map::DistanceMapOptions{}.clamp_distance_m;
  // The plain GPF mean, without the Gauss-Newton refinement odometry uses:
  // in the true map (60 s of tunnel) refinement cost rotation accuracy
  // (rotation RMSE fixed VLP-16 0.120 -> 0.230 deg, rotating Hokuyo 0.216
  // -> 0.343 deg, rotating VLP-16 0.159 -> 0.150 deg).
  o.gpf.refine_iterations = 0;
  // Without refinement the particles are the estimate: all of them.
  o.gpf.num_particles = matching::GpfOptions{}.num_particles;
  // Point to plane (GpfOptions::point_to_plane, `unimap localize
  // --point-to-plane`) stays off: in the true tunnel map it cut the 60 s
  // position / rotation RMSE (fixed VLP-16 0.020 / 0.078 -> 0.016 / 0.064,
  // rotating VLP-16 0.018 / 0.091 -> 0.012 / 0.063, rotating Hokuyo 0.015 /
  // 0.072 -> 0.011 / 0.054) but not the full flights' position RMSE (fixed
  // VLP-16 0.045 -> 0.053 m, rotating VLP-16 0.019 -> 0.020, rotating Hokuyo
  // 0.020 -> 0.023; rotation 0.040 / 0.054 / 0.049 -> 0.036 / 0.049 / 0.042 deg).
  // Particles spread at least 3 cm and 0.01 rad, wider than the IMU's
  // prediction between two scans, so that their weights resolve the scan's
  // likelihood in a complete map instead of echoing Monte-Carlo noise (ESS
  // near K). 60 s of tunnel, position / rotation RMSE, floors 5 mm and
  // 0.001 rad -> these: fixed VLP-16 0.037 / 0.082 -> 0.022 / 0.064,
  // rotating Hokuyo 0.081 / 0.227 -> 0.047 / 0.134, rotating VLP-16 (0.3 m
  // map) 0.081 / 0.151 -> 0.075 / 0.169. Odometry keeps the narrow floors:
  // in its growing map the wide particles lock onto the unmapped edges
  // (hallway, rotating Hokuyo: ATE 0.80 m -> 11 m).
  o.gpf.min_sigma_position_m = 0.03;
  o.gpf.min_sigma_rotation_rad = 0.01;
  // Bias random walks of the simulated IMU (the ADIS16448 figures Kalibr
  // ships, 2e-4 m/s^2/sqrt(s) and 2e-5 rad/s/sqrt(s)), twice the odometry
  // defaults. In a fixed map the bias follows the scans' evidence; where a
  // scan says nothing about the height (fixed VLP-16, 20 s hover behind the
  // last car of the tunnel) the height is the IMU's, and a stale accelerometer
  // bias let it drift 0.48 m. Full tunnel flight, position / rotation RMSE:
  // fixed VLP-16 0.060 / 0.047 -> 0.045 / 0.040, rotating Hokuyo 0.025 /
  // 0.059 -> 0.020 / 0.049, rotating VLP-16 (0.1 m) 0.025 / 0.074 -> 0.019 /
  // 0.054. Odometry keeps the stiffer bias: in a map built from its own
  // estimates the corridor loop's ATE went 0.084 -> 0.183 m with these.
  o.eskf.accel_bias_walk_m_s2_sqrt_s = 2e-4;
  o.eskf.gyro_bias_walk_rad_s_sqrt_s = 2e-5;
  return o;
}

}  // namespace unimap::pipeline
