#pragma once
#include <list>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "graph/LoopClosureMatcher.hpp"
#include "graph/LoopClosureOptions.hpp"
#include "map/Submap.hpp"
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
};

// Finds loop closures for 3D scans among retired submaps (docs/design.md 1.5):
// candidates are retired submaps (not the newest few, which overlap the live
// ones) whose optimised origin lies within the search radius plus the
// submap's reach of the scan's world estimate; the radius grows with the
// distance travelled since the submap (drift). Each candidate is matched by
// graph::LoopClosureMatcher, whose matchers are cached (least recently used
// dropped). Not thread-safe: the Mapper calls it from one thread at a time.
class LoopClosureFinder {
 public:
  LoopClosureFinder(const LoopSearchOptions& search, const graph::LoopClosureOptions& matcher);

  // Keeps a retired submap; path_m: distance travelled when it was retired.
  void AddRetired(map::RetiredSubmap submap, double path_m);
  // Tries the key scan (points in the body frame) against the candidates;
  // returns the accepted closures (at most one per candidate submap).
  std::vector<LoopClosure> Search(int key_scan, const std::vector<Eigen::Vector3f>& points_body,
                                  const Eigen::Isometry3d& T_world_body, double path_m, const TrajectoryGraph& graph);
  const LoopSearchStats& stats() const { return stats_; }
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
  std::vector<Retired> retired_;
  // Cache: (retired index, matcher), most recently used first.
  std::list<std::pair<std::size_t, std::unique_ptr<graph::LoopClosureMatcher>>> cache_;
  LoopSearchStats stats_;
  std::vector<std::string> messages_;
};

}  // namespace unimap::pipeline
