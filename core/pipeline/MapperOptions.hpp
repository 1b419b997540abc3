#pragma once
#include <string>

#include "graph/LoopClosureOptions.hpp"
#include "graph/PoseGraphOptions.hpp"
#include "map/SubmapOptions.hpp"
#include "pipeline/LocalizerOptions.hpp"
#include "unimap/CoreParameters.hpp"

namespace unimap::pipeline {

// Loop-closure scheduling: which retired submaps a 3D scan is tried against.
struct LoopSearchOptions {
  bool enabled = true;              // search for loop closures at all
  int every_3d_scans = 2;           // try every this many 3D scans
  int skip_recent_submaps = 2;      // the newest retired submaps overlap the live ones: not loops
  double min_radius_m = 1.0;        // search radius (xy) with no drift since the submap (m)
  double radius_per_path_m = 0.03;  // radius grows by this per metre travelled since the submap
  double max_radius_m = 5.0;        // upper bound of the search radius (m)
  double submap_reach_m = 10.0;     // a submap is a candidate when its origin is within
                                    // radius + this of the scan's estimated position (m)
  int max_candidates = 2;           // nearest candidates tried per 3D scan
  int max_cached_matchers = 6;      // loop-closure matchers kept in memory (least recently used dropped)
  double min_path_m = 5.0;          // a submap is a candidate only after this much travel since it (m)
  double redundant_overlap = 0.9;   // a retired submap with at least this share of its surface voxels in
                                    // the last kept one's adds nothing to search: its surface is dropped
                                    // (a slow or hovering sensor retires the same place again and again)

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
};

// Everything the mapper needs. Per-platform values (the paper's N, M, I,
// sigmas, resolution, max range) come from the payload's CoreParameters.
struct MapperOptions {
  LocalizerOptions localizer;              // ESKF, GPF, N, local map settings
  map::SubmapOptions submaps;              // M and each submap's octree / distance map
  int scans_3d_per_optimization = 10;      // I: optimise the pose graph every this many 3D scans
  graph::PoseGraphOptions graph;           // solver settings
  graph::LoopClosureOptions loop_closure;  // matcher settings
  LoopSearchOptions loop_search;           // candidate selection
  double scan_sigma_position_m = 0.1;      // scan-in-submap and odometry constraints: position sigma (m), the
                                           // order of the localiser's along-track error over a submap
  double scan_sigma_rotation_rad = 0.001;  // ... and rotation sigma (rad): the localiser's rotation drifts far
                                           // less than its position (measured: docs/mapping.md, "Pose graph")
  bool wait_for_background = true;         // offline: wait for each optimisation and loop search so
                                           // results do not depend on machine speed; live: false

  // Every field by name, for the platform file's `mapper:` section: the
  // localiser's fields at the top level (LocalizerOptions::VisitFields),
  // then graph, loop_closure, loop_search and this struct's own.
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
  // Shared defaults with the platform's parameters.
  static MapperOptions FromPlatform(const CoreParameters& core);
};

}  // namespace unimap::pipeline
