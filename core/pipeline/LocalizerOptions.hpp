#pragma once
#include <optional>
#include <string>

#include "estimation/EskfOptions.hpp"
#include "estimation/MotionPriorOptions.hpp"
#include "estimation/StaticInitializer.hpp"
#include "map/DistanceMapOptions.hpp"
#include "map/LineGapFill.hpp"
#include "map/NeighborhoodPlane.hpp"
#include "matching/GpfOptions.hpp"
#include "pipeline/Reacquirer.hpp"
#include "unimap/CoreParameters.hpp"

namespace unimap::pipeline {

// Everything the localiser needs; per-platform values come from the
// payload's CoreParameters (FromPlatform), the rest are shared defaults.
struct LocalizerOptions {
  using InitialAttitude = estimation::InitialAttitude;
  estimation::EskfOptions eskf;           // IMU noise (sigma_a, sigma_g) and initial uncertainty
  estimation::MotionPriorOptions motion;  // prediction source (IMU, or a prior for data without one)
  matching::GpfOptions gpf;               // particles, likelihood, downsampling
  map::DistanceMapOptions map;            // resolution and box (distance-map max range)
  ReacquireOptions reacquire;             // the wide search when a prediction is uncertain or a match poor
  int scans_per_3d_scan = 1;              // N: scans accumulated before a map insertion
  double static_init_s = 1.0;             // IMU window at the start used to align with gravity (s)
  InitialAttitude initial_attitude = InitialAttitude::kGravity;  // with a given initial pose
  double max_initial_accel_bias_m_s2 = 0.3;  // kPose: a larger implied bias means the pose's tilt is
                                             // wrong (1.75 deg at 0.3): gravity alignment is used instead
  int min_points_to_match = 30;              // scans with fewer body points are inserted unmatched
  double max_predicted_distance_m = 0.0;     // > 0: points farther than this from the map at the
                                             // predicted pose are not measured (GaussianParticleFilter::Match;
                                             // FromPlatform: 1.5 voxels). 0: all measured
  double sweep_gate_sigmas = 3.0;            // the gate above widens by this many sigmas of the pose's
                                             // uncertainty relative to the map, so an uncertain prediction
                                             // keeps its points: range x rotation for every scan, plus
                                             // position for 3D sweeps (ScanMatcher::Match)
  bool localize_only = false;                // true: a prior map is given and never modified
  double max_scan_latency_s = 0.5;           // a scan still lacking encoder coverage this long after its end is skipped
  bool trilinear_distance = true;            // GPF reads the distance map trilinearly (false: nearest voxel)
  std::optional<map::NeighborhoodPlaneOptions>
      neighborhood_planes;  // set: point to plane with planes
                            // fitted to the map's surface cells around each point
                            // (FitNeighborhoodPlane, these settings) instead of the field's
                            // cell planes; needs gpf.point_to_plane
  std::optional<map::LineGapFillOptions> line_gap_fill =
      map::LineGapFillOptions{};  // set: line scans
                                  // also insert the surface between consecutive lines into the
                                  // distance map (LineGapFill; not into key scans or the map files)
  bool wait_for_map = true;       // wait for each map insertion to be published before matching on:
                                  // offline runs then do not depend on machine speed; live use sets
                                  // false so localisation never waits (the map catches up in the background)

  // Every field by name, for the platform file's `mapper:` section: the
  // sections eskf, motion, gpf, map, reacquire and line_gap_fill (its
  // `enabled` says whether it is set), then this struct's own fields.
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
  // Plane matching (`unimap run --plane-matching`): every scan point is tied
  // to the plane fitted to the map's surface cells around it
  // (neighborhood_planes, gpf.point_to_plane) and points without one are
  // not measured (gpf.planes_only); no line gap fill. A rotating line
  // scanner's map is made of stripes; measured against the nearest stripe
  // instead of across the surface, a point beside it pulls the pose along
  // the surface (docs/mapping.md, known limitation).
  void UsePlaneMatching();
  // map.clamp_distance_m = the particle filter's clamp, at least one map
  // voxel: the likelihood and the refinement read no farther (FromPlatform;
  // unimap localize for a .pcd prior map, after setting its resolution).
  void ClampFieldAtLikelihood();
  // Shared defaults with the platform's N, sigmas, resolution and max range.
  static LocalizerOptions FromPlatform(const CoreParameters& core);
  // FromPlatform tuned for tracking in a fixed, complete prior map (unimap
  // localize): localize_only, sub-voxel surfaces, wide particles, the
  // plain GPF mean, the IMU's full bias walk, and a distance map no coarser
  // than kPriorMapResolutionM (a .bt map keeps its own resolution).
  static LocalizerOptions ForPriorMap(const CoreParameters& core);
  // The finest voxel edge a prior map gets by default (m): the voxel `unimap
  // run` filters its map.pcd to, so a finer field would add no detail.
  static constexpr double kPriorMapResolutionM = 0.1;
};

}  // namespace unimap::pipeline
