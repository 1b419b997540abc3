#include "map/OccupancyTree.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <octomap/OcTree.h>

#include "unimap/Errors.hpp"

namespace unimap::map {

namespace {

Eigen::Vector3i FromOctreeKey(const octomap::OcTreeKey& key) { return Eigen::Vector3i(key[0], key[1], key[2]); }

octomap::OcTreeKey ToOctreeKey(const Eigen::Vector3i& key) {
  return octomap::OcTreeKey(static_cast<octomap::key_type>(key.x()), static_cast<octomap::key_type>(key.y()),
                            static_cast<octomap::key_type>(key.z()));
}

// 16-bit keys packed into one integer for the hash sets.
std::uint64_t Pack(const Eigen::Vector3i& key) { return SurfacePoints::Pack(key); }

Eigen::Vector3i Unpack(std::uint64_t packed) {
  return Eigen::Vector3i(static_cast<int>((packed >> 32) & 0xffff), static_cast<int>((packed >> 16) & 0xffff),
                         static_cast<int>(packed & 0xffff));
}

// Calls visit(min_key, size_voxels) for every occupied leaf inside within.
template <class Visit>
void ForEachOccupiedLeaf(const octomap::OcTree& tree, const KeyBox* within, Visit visit) {
  const int depth = static_cast<int>(tree.getTreeDepth());
  auto handle = [&](const auto& it) {
    if (!tree.isNodeOccupied(*it)) return;
    visit(FromOctreeKey(it.getIndexKey()), 1 << (depth - static_cast<int>(it.getDepth())));
  };
  if (within == nullptr) {
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) handle(it);
    return;
  }
  for (auto it = tree.begin_leafs_bbx(ToOctreeKey(within->min()), ToOctreeKey(within->max())),
            end = tree.end_leafs_bbx();
       it != end; ++it) {
    handle(it);
  }
}

}  // namespace

OccupancyTree::OccupancyTree(const DistanceMapOptions& options)
    : options_(options),
      tree_(std::make_unique<octomap::OcTree>(options.resolution_m)),
      resolution_m_(options.resolution_m),
      tracks_occupied_(options.raycast_free_space && options.clear_occupied_only) {
  if (options_.subvoxel_surfaces) surfaces_ = std::make_unique<SurfacePoints>(resolution_m_, options_.signed_surfaces);
  ApplySensorModel();
}

OccupancyTree::OccupancyTree(std::unique_ptr<octomap::OcTree> tree, const DistanceMapOptions& options)
    : options_(options),
      tree_(std::move(tree)),
      resolution_m_(0.0),
      tracks_occupied_(options.raycast_free_space && options.clear_occupied_only) {
  if (tree_ == nullptr) throw InputError("OccupancyTree: null octree");
  resolution_m_ = tree_->getResolution();
  if (options_.subvoxel_surfaces) surfaces_ = std::make_unique<SurfacePoints>(resolution_m_, options_.signed_surfaces);
  ApplySensorModel();
  if (!tracks_occupied_) return;
  // A leaf above the finest depth stands for size^3 voxels, each tracked
  // below: refuse a tree that would expand past max_occupied_voxels (a
  // damaged or hostile file: a leaf at depth 1 covers 2^45 voxels) before
  // allocating any.
  const std::uint64_t max_voxels = options_.max_occupied_voxels;
  std::uint64_t voxels = 0;
  ForEachOccupiedLeaf(*tree_, nullptr, [&voxels, max_voxels](const Eigen::Vector3i&, int size) {
    const auto edge = static_cast<std::uint64_t>(size);
    voxels = std::min<std::uint64_t>(voxels + edge * edge * edge, max_voxels + 1);
  });
  if (voxels > max_voxels) {
    throw InputError("octree: its occupied leaves cover more than " + std::to_string(max_voxels) + " voxels of " +
                     std::to_string(resolution_m_) + " m (coarse occupied leaves near the root); not a surface map");
  }
  ForEachOccupiedLeaf(*tree_, nullptr, [this](const Eigen::Vector3i& min_key, int size) {
    for (int dx = 0; dx < size; ++dx) {
      for (int dy = 0; dy < size; ++dy) {
        for (int dz = 0; dz < size; ++dz) occupied_.insert(Pack(min_key + Eigen::Vector3i(dx, dy, dz)));
      }
    }
  });
}

OccupancyTree::~OccupancyTree() = default;

void OccupancyTree::ApplySensorModel() {
  tree_->setProbHit(options_.prob_hit);
  tree_->setProbMiss(options_.prob_miss);
  tree_->setOccupancyThres(options_.occupancy_threshold);
  tree_->setClampingThresMin(options_.clamp_min_probability);
  tree_->setClampingThresMax(options_.clamp_max_probability);
}

KeyBox OccupancyTree::Insert(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& origin_map) {
  if (options_.raycast_free_space && !options_.clear_occupied_only) {
    return InsertWithOctomap(points_map, origin_map);
  }
  const float max_range_m = static_cast<float>(options_.max_insert_range_m);
  KeyBox endpoints;
  KeySetType hits;
  KeySetType cut_ends;                // voxels of rays cut at the range (deduplicated)
  std::vector<Eigen::Vector3f> ends;  // where the rays end
  hits.reserve(points_map.size());
  for (const Eigen::Vector3f& p : points_map) {
    const Eigen::Vector3f ray = p - origin_map;
    if (ray.squaredNorm() > max_range_m * max_range_m) {
      const Eigen::Vector3f end = origin_map + ray.normalized() * max_range_m;
      if (!options_.discretize_rays || cut_ends.insert(Pack(KeyOf(end))).second) ends.push_back(end);
      continue;
    }
    const Eigen::Vector3i key = KeyOf(p);
    endpoints.Extend(key);
    const bool first_in_voxel = hits.insert(Pack(key)).second;
    if (surfaces_ != nullptr) surfaces_->Add(Pack(key), KeyCenter(key), p, &origin_map);
    if (!options_.discretize_rays) {
      ends.push_back(p);
    } else if (first_in_voxel) {
      ends.push_back(KeyCenter(key));
    }
  }
  if (options_.raycast_free_space) ClearOccupiedAlongRays(origin_map, ends, hits);
  if (surfaces_ == nullptr) {
    for (const std::uint64_t key : hits) UpdateVoxel(Unpack(key), true);
    return endpoints;
  }
  // In key order: refreshing a surface reads its neighbours' (SurfacePoints),
  // which the previous voxels have just brought into the cache.
  std::vector<std::uint64_t> hit_keys(hits.begin(), hits.end());
  std::sort(hit_keys.begin(), hit_keys.end());
  for (const std::uint64_t key : hit_keys) UpdateVoxel(Unpack(key), true);
  return endpoints;
}

void OccupancyTree::ClearOccupiedAlongRays(const Eigen::Vector3f& origin_map,
                                           const std::vector<Eigen::Vector3f>& ends_map, const KeySetType& hits) {
  if (occupied_.empty()) return;
  const octomap::point3d origin(origin_map.x(), origin_map.y(), origin_map.z());
  octomap::KeyRay ray;  // voxels from the origin's up to (excluding) the end's
  KeySetType to_clear;
  for (const Eigen::Vector3f& end : ends_map) {
    if (!tree_->computeRayKeys(origin, octomap::point3d(end.x(), end.y(), end.z()), ray)) continue;
    for (const octomap::OcTreeKey& key : ray) {
      const std::uint64_t packed = Pack(FromOctreeKey(key));
      if (occupied_.count(packed) != 0 && hits.count(packed) == 0) to_clear.insert(packed);
    }
  }
  for (const std::uint64_t key : to_clear) UpdateVoxel(Unpack(key), false);
}

KeyBox OccupancyTree::InsertWithOctomap(const std::vector<Eigen::Vector3f>& points_map,
                                        const Eigen::Vector3f& origin_map) {
  KeyBox endpoints;
  KeySetType hits;  // voxels of the returns (only to sync their surfaces)
  octomap::Pointcloud cloud;
  cloud.reserve(points_map.size());
  const float max_range_m = static_cast<float>(options_.max_insert_range_m);
  // Returns beyond the range only clear free space up to it: pull them in to
  // just past the range so far (or huge) coordinates never reach OctoMap's
  // key arithmetic, whose 16-bit keys would wrap when discretising.
  const float beyond_range_m = max_range_m + static_cast<float>(2.0 * resolution_m_);
  for (const Eigen::Vector3f& p : points_map) {
    const Eigen::Vector3f ray = p - origin_map;
    if (ray.squaredNorm() > max_range_m * max_range_m) {
      const Eigen::Vector3f end = origin_map + ray.normalized() * beyond_range_m;
      cloud.push_back(end.x(), end.y(), end.z());
      continue;
    }
    cloud.push_back(p.x(), p.y(), p.z());
    const Eigen::Vector3i key = KeyOf(p);
    endpoints.Extend(key);
    if (surfaces_ != nullptr) {
      surfaces_->Add(Pack(key), KeyCenter(key), p, &origin_map);
      hits.insert(Pack(key));
    }
  }
  const octomap::point3d origin(origin_map.x(), origin_map.y(), origin_map.z());
  tree_->insertPointCloud(cloud, origin, options_.max_insert_range_m, /*lazy_eval=*/false, options_.discretize_rays);
  if (surfaces_ == nullptr) return endpoints;
  for (const std::uint64_t key : hits) SyncSurface(Unpack(key));
  // Voxels the rays freed: only the tree's change detection (enabled while a
  // distance transform consumes it) names them; without it their stale
  // surfaces stay until the voxel is hit again (they are only read for
  // occupied voxels).
  if (tree_->isChangeDetectionEnabled()) {
    for (auto it = tree_->changedKeysBegin(), end = tree_->changedKeysEnd(); it != end; ++it) {
      const Eigen::Vector3i key = FromOctreeKey(it->first);
      if (surfaces_->Find(Pack(key)) != nullptr) SyncSurface(key);
    }
  }
  return endpoints;
}

void OccupancyTree::SyncSurface(const Eigen::Vector3i& key) {
  const octomap::OcTreeNode* node = tree_->search(ToOctreeKey(key));
  if (node != nullptr && tree_->isNodeOccupied(node)) {
    surfaces_->Refresh(Pack(key), KeyCenter(key));
  } else {
    surfaces_->Erase(Pack(key));
  }
}

void OccupancyTree::UpdateVoxel(const Eigen::Vector3i& key, bool hit) {
  const octomap::OcTreeNode* node = tree_->updateNode(ToOctreeKey(key), hit);
  const bool occupied = tree_->isNodeOccupied(node);
  if (surfaces_ != nullptr) {
    if (!occupied) {
      surfaces_->Erase(Pack(key));
    } else if (hit) {
      surfaces_->Refresh(Pack(key), KeyCenter(key));
    }
  }
  if (!tracks_occupied_) return;
  if (occupied) {
    occupied_.insert(Pack(key));
  } else {
    occupied_.erase(Pack(key));
  }
}

void OccupancyTree::MarkOccupied(const std::vector<Eigen::Vector3f>& points_map) {
  const float occupied_log_odds = tree_->getClampingThresMaxLog();
  KeySetType marked;  // voxels whose surfaces need a refresh
  for (const Eigen::Vector3f& p : points_map) {
    if (!p.allFinite()) continue;
    octomap::OcTreeKey key;
    if (!tree_->coordToKeyChecked(p.x(), p.y(), p.z(), key)) continue;
    tree_->setNodeValue(key, occupied_log_odds);
    const Eigen::Vector3i voxel = FromOctreeKey(key);
    if (tracks_occupied_) occupied_.insert(Pack(voxel));
    if (surfaces_ != nullptr) {
      surfaces_->Add(Pack(voxel), KeyCenter(voxel), p, /*sensor_map=*/nullptr);
      marked.insert(Pack(voxel));
    }
  }
  if (surfaces_ == nullptr) return;
  for (const std::uint64_t key : marked) surfaces_->Refresh(key, KeyCenter(Unpack(key)));
}

Eigen::Vector3i OccupancyTree::KeyOf(const Eigen::Vector3f& p_map) const {
  return FromOctreeKey(tree_->coordToKey(p_map.x(), p_map.y(), p_map.z()));
}

Eigen::Vector3f OccupancyTree::KeyCenter(const Eigen::Vector3i& key) const {
  const octomap::point3d c = tree_->keyToCoord(ToOctreeKey(key));
  return Eigen::Vector3f(c.x(), c.y(), c.z());
}

KeyBox OccupancyTree::OccupiedExtent(const KeyBox& within) const {
  KeyBox extent;
  if (within.IsEmpty()) return extent;
  ForEachOccupiedLeaf(*tree_, &within, [&](const Eigen::Vector3i& min_key, int size) {
    extent.Extend(KeyBox(min_key, min_key + Eigen::Vector3i::Constant(size - 1)));
  });
  return extent.Intersection(within);
}

std::vector<Eigen::Vector3f> OccupancyTree::OccupiedVoxelCenters() const {
  std::vector<Eigen::Vector3f> centers;
  ForEachOccupiedLeaf(*tree_, nullptr, [&](const Eigen::Vector3i& min_key, int size) {
    for (int dx = 0; dx < size; ++dx) {
      for (int dy = 0; dy < size; ++dy) {
        for (int dz = 0; dz < size; ++dz) {
          centers.push_back(KeyCenter(min_key + Eigen::Vector3i(dx, dy, dz)));
        }
      }
    }
  });
  return centers;
}

}  // namespace unimap::map
