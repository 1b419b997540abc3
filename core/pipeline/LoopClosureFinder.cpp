#include "pipeline/LoopClosureFinder.hpp"

#include <algorithm>
#include <cstdio>

namespace unimap::pipeline {

LoopClosureFinder::LoopClosureFinder(const LoopSearchOptions& search, const graph::LoopClosureOptions& matcher,
                                     double surface_voxel_m)
    : search_(search), matcher_options_(matcher), inv_voxel_(1.0 / surface_voxel_m) {}

void LoopClosureFinder::AddRetired(map::RetiredSubmap submap, double path_m) {
  // Consecutive submaps share M / 2 3D scans, so most of a submap's voxels
  // are in its predecessor's even while the sensor moves on; it is dropped
  // only when the last kept one holds redundant_overlap of them (measured
  // in docs/reliability.md, memory over long runs).
  const Eigen::Isometry3f T_local_submap = submap.T_local_submap.cast<float>();
  matching::VoxelKeySet voxels;
  std::size_t held = 0;
  for (const Eigen::Vector3f& p : submap.points_submap.Expand()) {
    const std::uint64_t key = matching::VoxelKey(T_local_submap * p, inv_voxel_);
    if (!voxels.insert(key).second) continue;
    held += last_kept_voxels_.count(key);
  }
  if (!retired_.empty() && !voxels.empty() &&
      static_cast<double>(held) >= search_.redundant_overlap * static_cast<double>(voxels.size())) {
    ++stats_.redundant;
    return;
  }
  last_kept_voxels_ = std::move(voxels);
  retired_.push_back({std::move(submap), path_m});
}

std::size_t LoopClosureFinder::retired_points() const {
  std::size_t n = 0;
  for (const Retired& r : retired_) n += r.submap.points_submap.size();
  return n;
}

std::size_t LoopClosureFinder::retired_bytes() const {
  std::size_t n = 0;
  for (const Retired& r : retired_) n += r.submap.points_submap.bytes();
  return n;
}

const graph::LoopClosureMatcher& LoopClosureFinder::Matcher(std::size_t index) {
  for (auto it = cache_.begin(); it != cache_.end(); ++it) {
    if (it->first == index) {
      cache_.splice(cache_.begin(), cache_, it);
      return *cache_.front().second;
    }
  }
  ++stats_.matchers_built;
  // The least recently used one goes before the new one is built: the
  // cache never holds more than max_cached_matchers (a matcher is 3-9 MiB).
  while (!cache_.empty() && cache_.size() >= static_cast<std::size_t>(search_.max_cached_matchers)) cache_.pop_back();
  cache_.emplace_front(index, std::make_unique<graph::LoopClosureMatcher>(retired_[index].submap.points_submap.Expand(),
                                                                          matcher_options_));
  return *cache_.front().second;
}

std::vector<LoopClosure> LoopClosureFinder::Search(int key_scan, const std::vector<Eigen::Vector3f>& points_body,
                                                   const Eigen::Isometry3d& T_world_body, double path_m,
                                                   const TrajectoryGraph& graph) {
  std::vector<LoopClosure> closures;
  const std::size_t eligible = retired_.size() > static_cast<std::size_t>(search_.skip_recent_submaps)
                                   ? retired_.size() - static_cast<std::size_t>(search_.skip_recent_submaps)
                                   : 0;
  // Candidates: (distance to the submap's origin, index, radius).
  struct Candidate {
    double distance_m;
    std::size_t index;
    double radius_m;
    Eigen::Isometry3d T_world_submap;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < eligible; ++i) {
    const Retired& r = retired_[i];
    const double traveled_m = path_m - r.path_m;
    if (traveled_m < search_.min_path_m) continue;
    Eigen::Isometry3d T_world_submap;
    if (!graph.T_world_submap(r.submap.id, &T_world_submap)) continue;
    const double radius_m =
        std::min(search_.max_radius_m, search_.min_radius_m + search_.radius_per_path_m * traveled_m);
    const double distance_m = (T_world_submap.translation() - T_world_body.translation()).norm();
    if (distance_m <= radius_m + search_.submap_reach_m)
      candidates.push_back({distance_m, i, radius_m, T_world_submap});
  }
  if (candidates.empty()) return closures;
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance_m < b.distance_m; });
  if (candidates.size() > static_cast<std::size_t>(search_.max_candidates)) {
    candidates.resize(static_cast<std::size_t>(search_.max_candidates));
  }
  ++stats_.searches;
  for (const Candidate& c : candidates) {
    ++stats_.candidates;
    const Eigen::Isometry3d guess = c.T_world_submap.inverse() * T_world_body;
    const graph::LoopClosureResult result = Matcher(c.index).Match(points_body, guess, c.radius_m);
    if (!result.accepted) {
      ++stats_.rejected;
      continue;
    }
    ++stats_.accepted;
    LoopClosure closure;
    closure.key_scan = key_scan;
    closure.submap_id = retired_[c.index].submap.id;
    closure.T_submap_body = result.T_submap_body;
    closure.covariance = result.covariance;
    closures.push_back(closure);
    char line[200];
    const Eigen::Vector3d shift = (result.T_submap_body.translation() - guess.translation());
    std::snprintf(line, sizeof line, "loop closure: 3D scan %d -> submap %d, score %.2f, shift %.2f m", key_scan,
                  closure.submap_id, result.score, shift.norm());
    messages_.emplace_back(line);
  }
  return closures;
}

std::vector<std::string> LoopClosureFinder::TakeMessages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

}  // namespace unimap::pipeline
