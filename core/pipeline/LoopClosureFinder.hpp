#pragma once
#include <list>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "graph/LoopClosureMatcher.hpp"
#include "graph/LoopClosureOptions.hpp"
#include "map/Submap.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "pipeline/MapperOptions.hpp"
#include "pipeline/TrajectoryGraph.hpp"

namespace unimap::pipeline {

// Counts of the loop-closure search.
struct LoopSearchStats {
  std::size_t searches = 0;        // 3D scans tried against at least one candidate
  std::size_t candidates = 0;      // scan-submap matches attempted
  std::size_t accepted = 0;        // matches that passed the matcher's checks
  std::size_t rejected = 0;        // matches that did not
  std::size_t matchers_built = 0;  // submap matchers constructed (cache misses)
  std::size_t redundant = 0;       // retired submaps whose surface the last kept one already held
};

// Finds loop closures for 3D scans among retired submaps (docs/design.md 1.5):
// candidates are retired submaps (not the newest few, which overlap the live
// ones) whose optimised origin lies within the search radius plus the
// submap's reach of the scan's world estimate; the radius grows with the
// distance travelled since the submap (drift). Each candidate is matched by
// graph::LoopClosureMatcher, whose matchers are cached (least recently used
// dropped). A retired submap whose surface voxels (local frame) lie mostly
// in the last kept one's is not kept: the place is already searchable, and
// a slow or hovering sensor would otherwise add a copy every M / 2 3D scans
// (docs/reliability.md, memory over long runs). Not thread-safe: the Mapper
// calls it from one thread at a time.
class LoopClosureFinder {
 public:
  // surface_voxel_m: the submaps' voxel edge (their surface points are voxel means).
  LoopClosureFinder(const LoopSearchOptions& search, const graph::LoopClosureOptions& matcher, double surface_voxel_m);

  // Keeps a retired submap unless redundant (above); path_m: distance
  // travelled when it was retired.
  void AddRetired(map::RetiredSubmap submap, double path_m);
  // Tries the key scan (points in the body frame) against the candidates;
  // returns the accepted closures (at most one per candidate submap).
  std::vector<LoopClosure> Search(int key_scan, const std::vector<Eigen::Vector3f>& points_body,
                                  const Eigen::Isometry3d& T_world_body, double path_m, const TrajectoryGraph& graph);
  const LoopSearchStats& stats() const { return stats_; }
  // Retired submaps kept as candidates.
  std::size_t retired_count() const { return retired_.size(); }
  // Surface points the retired submaps keep, and the bytes they take.
  std::size_t retired_points() const;
  std::size_t retired_bytes() const;
  // Messages about accepted closures (for the log), since the last call.
  std::vector<std::string> TakeMessages();

 private:
  struct Retired {
    map::RetiredSubmap submap;
    double path_m = 0.0;
  };
  const graph::LoopClosureMatcher& Matcher(std::size_t index);

  LoopSearchOptions search_;
  graph::LoopClosureOptions matcher_options_;
  double inv_voxel_;
  matching::VoxelKeySet last_kept_voxels_;  // the last kept submap's surface voxels, local frame
  std::vector<Retired> retired_;
  // Cache: (retired index, matcher), most recently used first.
  std::list<std::pair<std::size_t, std::unique_ptr<graph::LoopClosureMatcher>>> cache_;
  LoopSearchStats stats_;
  std::vector<std::string> messages_;
};

}  // namespace unimap::pipeline
