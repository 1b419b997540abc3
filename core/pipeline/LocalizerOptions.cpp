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
  if (neighborhood_planes) {
    if (!neighborhood_planes->IsValid(&inner)) {
      *why = "neighborhood_plane: " + inner;
      return false;
    }
    if (!gpf.point_to_plane) {
      *why = "neighborhood_planes needs gpf.point_to_plane";
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
  if (scans_per_3d_scan < 1 || !(static_init_s >= 0.0) || min_points_to_match < 1 || !(max_scan_latency_s > 0.0) ||
      !(max_initial_accel_bias_m_s2 > 0.0)) {
    *why =
        "scans_per_3d_scan and min_points_to_match must be >= 1, static_init_s >= 0, "
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
  // Why each value (measurements: docs/mapping.md, "The odometry defaults").
  LocalizerOptions o;
  o.scans_per_3d_scan = core.scans_per_3d_scan;
  o.eskf.sigma_accel_m_s2 = core.sigma_accel_m_s2;
  o.eskf.sigma_gyro_rad_s = core.sigma_gyro_rad_s;
  o.map.resolution_m = core.distance_map_resolution_m;
  o.map.max_range_m = core.distance_map_max_range_m;
  o.gpf.voxel_size_m = core.distance_map_resolution_m;
  // Distances to the surface inside each voxel, as magnitudes: voxel centres
  // are up to half a voxel off the surface, and that bias held a pitch
  // error that leaked gravity into the travel direction; signed distances
  // turned the tunnel's heading.
  o.map.subvoxel_surfaces = true;
  o.map.signed_surfaces = false;
  // Points farther than 1.5 voxels from the map at the predicted pose are
  // not measured: a scan reaches past what the map holds (the frontier, the
  // gaps between a line scanner's stripes), and such points, measured against
  // the nearest surface the map does hold, pull the pose back. 3D sweeps
  // widen the gate by the prediction's own uncertainty (ScanMatcher).
  o.max_predicted_distance_m = 1.5 * core.distance_map_resolution_m;
  // Returns farther than 100 voxels, where a voxel subtends less than 0.01
  // rad from the sensor, are kept in 3-voxel cells: outdoors they are most
  // of what a sweep maps, and each cost a surface element and rays at full
  // resolution (docs/mapping.md, "Fourth round: far returns in coarse cells").
  o.map.coarse_beyond_m = 100.0 * core.distance_map_resolution_m;
  // Gauss-Newton refinement of every match (PoseRefiner): the plain GPF's
  // Monte-Carlo noise made a static hallway run diverge.
  o.gpf.refine_iterations = 5;
  // The distance map is exact up to the particle filter's clamp and reads
  // that beyond: the likelihood and the refinement read no farther, and each
  // metre of exact distance costs propagation and memory.
  o.ClampFieldAtLikelihood();
  // The particles only place the refinement's start: 100 do it at a fifth
  // of the time of 500.
  o.gpf.num_particles = 100;
  return o;
}

void LocalizerOptions::ClampFieldAtLikelihood() {
  map.clamp_distance_m = std::max(gpf.clamp_distance_m, map.resolution_m);
}

void LocalizerOptions::UsePlaneMatching() {
  neighborhood_planes = map::NeighborhoodPlaneOptions{};
  gpf.point_to_plane = true;
  gpf.planes_only = true;
  // Planes are fitted across the measured stripes; filled gaps made them
  // worse (docs/mapping.md, "The odometry defaults").
  line_gap_fill.reset();
}

LocalizerOptions LocalizerOptions::ForPriorMap(const CoreParameters& core) {
  // Why each value differs from odometry (measurements: docs/localization.md,
  // "Settings that differ from odometry").
  LocalizerOptions o = FromPlatform(core);
  o.localize_only = true;
  // A fixed, complete map: signed distances to the surface inside each
  // voxel, and every line point measured.
  o.map.subvoxel_surfaces = true;
  o.map.signed_surfaces = true;
  o.max_predicted_distance_m = 0.0;
  // The field is computed once, not grown: the coarse grid a payload maps
  // with for speed is not needed.
  o.map.resolution_m = std::min(o.map.resolution_m, kPriorMapResolutionM);
  o.gpf.voxel_size_m = o.map.resolution_m;
  o.map.coarse_beyond_m = 0.0;  // a prior map's points have no sensor to be far from
  // The default clamp (unimap localize clamps a .pcd map's field at the
  // particle filter's clamp itself; a .bt map's resolution may be coarser).
  o.map.clamp_distance_m = map::DistanceMapOptions{}.clamp_distance_m;
  // The plain GPF mean: in the true map refinement cost rotation accuracy.
  // Without refinement the particles are the estimate: all of them.
  o.gpf.refine_iterations = 0;
  o.gpf.num_particles = matching::GpfOptions{}.num_particles;
  // Particles spread wider than the IMU's prediction between two scans, so
  // that their weights resolve the scan's likelihood instead of echoing
  // Monte-Carlo noise (odometry keeps the narrow floors: in a growing map
  // wide particles lock onto its unmapped edges).
  o.gpf.min_sigma_position_m = 0.03;
  o.gpf.min_sigma_rotation_rad = 0.01;
  // The simulated IMU's bias random walks (the ADIS16448 figures Kalibr
  // ships), twice odometry's: in a fixed map the bias can follow the scans'
  // evidence.
  o.eskf.accel_bias_walk_m_s2_sqrt_s = 2e-4;
  o.eskf.gyro_bias_walk_rad_s_sqrt_s = 2e-5;
  return o;
}

}  // namespace unimap::pipeline
