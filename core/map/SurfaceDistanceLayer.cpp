#include "map/SurfaceDistanceLayer.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace unimap::map {
namespace {

constexpr int kKeyOffset = 32768;  // voxel key of coordinate 0
constexpr int kMaxKey = 65535;
constexpr int kEdge = DistanceField::kBlockEdge;
constexpr int kMask = kEdge - 1;
constexpr std::uint16_t kFar = std::numeric_limits<std::uint16_t>::max();  // no occupied voxel within reach

const std::array<Eigen::Vector3i, 6> kSteps = {Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(-1, 0, 0),
                                               Eigen::Vector3i(0, 1, 0), Eigen::Vector3i(0, -1, 0),
                                               Eigen::Vector3i(0, 0, 1), Eigen::Vector3i(0, 0, -1)};

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

float LogOdds(double probability) { return static_cast<float>(std::log(probability / (1.0 - probability))); }

Eigen::Vector3i BlockOf(const Eigen::Vector3i& key) {
  return key.unaryExpr([](int v) { return v >> DistanceField::kBlockShift; });
}

Eigen::Vector3i Unpack(std::uint64_t packed) {
  return Eigen::Vector3i(static_cast<int>((packed >> 32) & 0xffff), static_cast<int>((packed >> 16) & 0xffff),
                         static_cast<int>(packed & 0xffff));
}

std::size_t CellOffset(const Eigen::Vector3i& key) {
  return static_cast<std::size_t>(DistanceField::BlockOffset(key.x() & kMask, key.y() & kMask, key.z() & kMask));
}

// Offset steps of a cell within its block along x, y, z (DistanceField::BlockOffset).
constexpr int kCellStride[3] = {DistanceField::BlockOffset(1, 0, 0), DistanceField::BlockOffset(0, 1, 0),
                                DistanceField::BlockOffset(0, 0, 1)};

template <std::size_t N>
bool Empty(const std::array<std::uint64_t, N>& mask) {
  return std::all_of(mask.begin(), mask.end(), [](std::uint64_t word) { return word == 0; });
}

bool InKeyRange(const Eigen::Vector3i& key) { return (key.array() >= 0).all() && (key.array() <= kMaxKey).all(); }

// True when after differs from before enough to recompute the distances to
// it (SurfaceDistanceLayer::kMoveTolerance).
bool Differs(const SurfacePoints::Element& before, const SurfacePoints::Element& after, float resolution_m) {
  if (before.planar != after.planar || before.oriented != after.oriented || before.scale != after.scale) return true;
  float change_voxels = (before.mean_m - after.mean_m).norm() / resolution_m;
  if (after.planar) {
    change_voxels += SurfacePoints::kPatchRadius * after.scale * before.normal.cross(after.normal).norm();
  }
  return change_voxels > SurfaceDistanceLayer::kMoveTolerance;
}

// True when the ray from sensor_map to the return in end_voxel_center_map
// passes through the surface of element: always for elements without a
// plane; for planar ones, when the ray crosses the plane with its end
// clearly behind it (by more than the voxel centre may misplace the return
// along the normal: half a cell per axis, |n|_1 end_scale res / 2) within
// the element's disk. A ray grazing a floor or wall runs through the voxels of
// that surface before its return without crossing it (docs/design.md 1.4):
// those are not misses.
bool CrossesElement(const SurfacePoints::Element& element, const Eigen::Vector3f& sensor_map,
                    const Eigen::Vector3f& end_voxel_center_map, float end_scale, float resolution_m) {
  if (!element.planar) return true;
  const float h_start = element.normal.dot(sensor_map - element.mean_m);
  const float h_end = element.normal.dot(end_voxel_center_map - element.mean_m);
  const float margin = 0.5f * end_scale * resolution_m * element.normal.cwiseAbs().sum();
  if (!((h_start > 0.0f && h_end < -margin) || (h_start < 0.0f && h_end > margin))) return false;
  const Eigen::Vector3f crossing = sensor_map + (h_start / (h_start - h_end)) * (end_voxel_center_map - sensor_map);
  const float radius = SurfacePoints::kPatchRadius * element.scale * resolution_m;
  return (crossing - element.mean_m).squaredNorm() <= radius * radius;
}

}  // namespace

bool SurfaceDistanceLayer::RayCrossesSurface(const Site& site, const Eigen::Vector3f& sensor_map,
                                             const Eigen::Vector3f& end_voxel_center_map, float end_scale) const {
  return site.element == nullptr || CrossesElement(*site.element, sensor_map, end_voxel_center_map, end_scale,
                                                   static_cast<float>(options_.resolution_m));
}

struct SurfaceDistanceLayer::WorkBlock {
  Eigen::Vector3i key = Eigen::Vector3i::Zero();                      // block coordinates
  std::array<std::uint16_t, DistanceField::kBlockCells> sq_distance;  // to the nearest occupied voxel centre (voxels^2)
  std::array<Site*, DistanceField::kBlockCells> owner;                // that voxel
  bool dirty = true;                                                  // to recompute at the next export
  std::array<std::uint64_t, DistanceField::kBlockCells / 64> dirty_cells{};  // ... these cells of it
  std::shared_ptr<const DistanceField::Block> exported;                      // as of the last export (null: all clamp)
  // The blocks across its faces (+x, -x, +y, -y, +z, -z; kSteps' order)
  // once a wave has crossed there: blocks are never removed.
  std::array<WorkBlock*, 6> neighbors{};

  // Marks a cell for recomputation at the next export.
  void Touch(std::size_t offset) {
    dirty = true;
    dirty_cells[offset >> 6] |= std::uint64_t{1} << (offset & 63u);
  }
};

SurfaceDistanceLayer::SurfaceDistanceLayer(const DistanceMapOptions& options)
    : options_(options),
      clamp_m_(static_cast<float>(options.clamp_distance_m)),
      reach_(static_cast<int>(std::ceil(options.clamp_distance_m / options.resolution_m)) + 1),
      log_odds_hit_(LogOdds(options.prob_hit)),
      log_odds_miss_(LogOdds(options.prob_miss)),
      log_odds_min_(LogOdds(options.clamp_min_probability)),
      log_odds_max_(LogOdds(options.clamp_max_probability)),
      distances_(options.compute_distances),
      surfaces_(options.resolution_m, /*signed_distances=*/false) {}

SurfaceDistanceLayer::~SurfaceDistanceLayer() = default;

bool SurfaceDistanceLayer::KeyOf(const Eigen::Vector3f& p_map, Eigen::Vector3i* key) const {
  const Eigen::Vector3d k = (p_map.cast<double>() / options_.resolution_m).array().floor() + kKeyOffset;
  if (!((k.array() >= 0.0).all() && (k.array() <= kMaxKey).all())) return false;
  *key = k.cast<int>();
  return true;
}

Eigen::Vector3f SurfaceDistanceLayer::Center(const Eigen::Vector3i& key) const {
  return ((key.cast<double>().array() - kKeyOffset + 0.5) * options_.resolution_m).cast<float>().matrix();
}

SurfaceDistanceLayer::WorkBlock* SurfaceDistanceLayer::BlockAt(const Eigen::Vector3i& key, bool create) {
  const Eigen::Vector3i block = BlockOf(key);
  const std::uint64_t packed = SurfacePoints::Pack(block);
  const auto it = blocks_.find(packed);
  if (it != blocks_.end()) return it->second.get();
  if (!create) return nullptr;
  auto fresh = std::make_unique<WorkBlock>();
  fresh->key = block;
  fresh->sq_distance.fill(kFar);
  fresh->owner.fill(nullptr);
  block_min_ = block_min_.cwiseMin(block);
  block_max_ = block_max_.cwiseMax(block);
  return blocks_.emplace(packed, std::move(fresh)).first->second.get();
}

void SurfaceDistanceLayer::Insert(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& sensor_map) {
  const auto start = std::chrono::steady_clock::now();
  ++scans_;
  // The voxels the returns fell in, with their surface slots.
  std::vector<std::pair<std::uint64_t, SurfacePoints::Slot>> hit;
  hit.reserve(points_map.size());
  // Far returns go to the middle voxel of their coarse cell (DistanceMapOptions::coarse_beyond_m).
  constexpr int kCell = DistanceMapOptions::kCoarseCell;
  const float coarse_sq = static_cast<float>(options_.coarse_beyond_m * options_.coarse_beyond_m);
  for (const Eigen::Vector3f& p : points_map) {
    Eigen::Vector3i key;
    if (!p.allFinite() || !KeyOf(p, &key)) {
      ++counts_.points_out_of_range;
      continue;
    }
    float scale = 1.0f;
    if (coarse_sq > 0.0f && (p - sensor_map).squaredNorm() > coarse_sq) {
      const Eigen::Vector3i middle = (key / kCell) * kCell + Eigen::Vector3i::Constant(kCell / 2);
      if (InKeyRange(middle)) {
        key = middle;
        scale = static_cast<float>(kCell);
        ++counts_.points_coarse;
      }
    }
    const std::uint64_t packed = SurfacePoints::Pack(key);
    hit.emplace_back(packed, surfaces_.Add(packed, Center(key), p, &sensor_map, scale));
    ++counts_.points_added;
  }
  std::sort(hit.begin(), hit.end());  // a deterministic order (a key has one slot)
  hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
  std::vector<Site*> touched_sites(hit.size());
  // Hits: one per voxel and scan (as OctoMap counts a discretised scan).
  std::vector<Site*> appeared;
  for (std::size_t i = 0; i < hit.size(); ++i) {
    const std::uint64_t packed = hit[i].first;
    const Eigen::Vector3i key = Unpack(packed);
    const SurfacePoints::Element* element = surfaces_.Refresh(hit[i].second, packed, Center(key));
    auto found = sites_.find(packed);
    if (found == sites_.end()) {
      site_store_.emplace_back();
      found = sites_.emplace(packed, &site_store_.back()).first;
    }
    Site& site = *found->second;
    touched_sites[i] = &site;
    site.key = key;
    site.element = element;
    site.log_odds = std::min(site.log_odds + log_odds_hit_, log_odds_max_);
    site.missed_in = scans_;  // a hit wins over the scan's misses (as in OctoMap)
    if (!site.occupied && site.log_odds > 0.0f) {
      SetOccupied(&site, true);
      appeared.push_back(&site);
    }
    if (site.occupied) Settle(site.key);  // rays skip it (a hit this scan)
  }
  std::vector<Site*> freed;
  if (options_.raycast_free_space) {
    const auto carve = std::chrono::steady_clock::now();
    Carve(touched_sites, sensor_map, &freed);
    counts_.carve_s += SecondsSince(carve);
  }
  counts_.surface_s += SecondsSince(start);
  if (!distances_) return;
  const auto waves = std::chrono::steady_clock::now();
  for (Site* site : freed) Refill(site);
  for (Site* site : appeared) Wave(site);
  Spread();
  for (Site* site : touched_sites) {
    if (site->waved) MarkIfChanged(site, false);
  }
  counts_.distance_s += SecondsSince(waves);
}

void SurfaceDistanceLayer::SetOccupied(Site* site, bool occupied) {
  if (site->occupied != occupied) occupied ? ++occupied_ : --occupied_;
  site->occupied = occupied;
  const std::size_t bit = CellOffset(site->key);
  const std::uint64_t packed_block = SurfacePoints::Pack(BlockOf(site->key));
  if (occupied) {
    auto& mask = occupied_masks_[packed_block].occupied;  // zero-initialised when new
    mask[bit / 64] |= std::uint64_t{1} << (bit % 64);
    return;
  }
  // An emptied block keeps its (all-zero) entry: erasing moves other
  // entries of the table, which Carve's cache points to (it erases them after).
  const auto it = occupied_masks_.find(packed_block);
  if (it == occupied_masks_.end()) return;
  it.value().occupied[bit / 64] &= ~(std::uint64_t{1} << (bit % 64));
}

void SurfaceDistanceLayer::Settle(const Eigen::Vector3i& key) {
  const auto it = occupied_masks_.find(SurfacePoints::Pack(BlockOf(key)));
  if (it == occupied_masks_.end()) return;
  BlockMasks& masks = it.value();
  if (masks.settled_in != scans_) {
    masks.settled.fill(0);
    masks.settled_in = scans_;
  }
  const std::size_t bit = CellOffset(key);
  masks.settled[bit / 64] |= std::uint64_t{1} << (bit % 64);
}

void SurfaceDistanceLayer::Carve(const std::vector<Site*>& ends, const Eigen::Vector3f& sensor_map,
                                 std::vector<Site*>* freed) {
  // Rays in key units from the sensor to the centre of each return's voxel,
  // that voxel excluded (RayWalk).
  const Eigen::Vector3d origin =
      sensor_map.cast<double>() / options_.resolution_m + Eigen::Vector3d::Constant(kKeyOffset);
  // Rays fan out from one sensor: most cross the blocks other rays just
  // crossed. A direct-mapped cache saves their hash look-ups; masks change
  // between scans (hits), so it starts empty.
  mask_cache_.assign(kMaskCacheSize, MaskCacheEntry{});
  const auto lookup = [this](const Eigen::Vector3i& block) {
    const std::uint64_t packed_block = SurfacePoints::Pack(block);
    MaskCacheEntry& entry = mask_cache_[KeyHash()(packed_block) & (kMaskCacheSize - 1)];
    if (entry.packed_block != packed_block) {
      auto it = occupied_masks_.find(packed_block);
      entry.packed_block = packed_block;
      entry.masks = it == occupied_masks_.end() ? nullptr : &it.value();
      entry.occupancy = BlockOccupancy{};
      if (entry.masks != nullptr && Empty(entry.masks->occupied)) entry.masks = nullptr;  // emptied by this Carve
      if (entry.masks != nullptr) {
        if (entry.masks->settled_in != scans_) {  // settled by an earlier scan: nothing is yet
          entry.masks->settled.fill(0);
          entry.masks->settled_in = scans_;
        }
        entry.occupancy.mask = &entry.masks->occupied;
        entry.occupancy.quarters = QuarterMask(entry.masks->occupied);
        entry.occupancy.settled = &entry.masks->settled;
      }
    }
    return entry.occupancy;
  };
  // Marks voxel settled for the rest of the scan (its block was just looked up).
  const auto settle = [this](const Eigen::Vector3i& voxel) {
    const std::uint64_t packed_block = SurfacePoints::Pack(BlockOf(voxel));
    const MaskCacheEntry& entry = mask_cache_[KeyHash()(packed_block) & (kMaskCacheSize - 1)];
    if (entry.packed_block != packed_block || entry.masks == nullptr) return;
    const std::size_t bit = CellOffset(voxel);
    entry.masks->settled[bit / 64] |= std::uint64_t{1} << (bit % 64);
  };
  for (const Site* end_site : ends) {
    const Eigen::Vector3i end = end_site->key;
    const Eigen::Vector3f end_center = Center(end);
    const float end_scale = end_site->element->scale;  // the cell the return stands for
    WalkRay(origin, end, lookup, [&](const Eigen::Vector3i& voxel) {
      Site& site = *sites_.at(SurfacePoints::Pack(voxel));
      if (site.missed_in == scans_) {  // hit or missed by this scan already
        settle(voxel);
        return false;
      }
      if (!RayCrossesSurface(site, sensor_map, end_center, end_scale)) return false;
      site.missed_in = scans_;
      settle(voxel);
      ++counts_.misses;
      site.log_odds = std::max(site.log_odds + log_odds_miss_, log_odds_min_);
      if (site.log_odds > 0.0f) return false;
      SetOccupied(&site, false);
      // Its block's cached occupancy is stale: the walk looks it up again.
      const std::uint64_t packed_block = SurfacePoints::Pack(BlockOf(voxel));
      mask_cache_[KeyHash()(packed_block) & (kMaskCacheSize - 1)] = MaskCacheEntry{};
      ++counts_.voxels_cleared;
      freed->push_back(&site);
      return true;
    });
  }
  // Blocks left without an occupied voxel hold none any more.
  for (const Site* site : *freed) {
    const auto it = occupied_masks_.find(SurfacePoints::Pack(BlockOf(site->key)));
    if (it != occupied_masks_.end() && Empty(it->second.occupied)) occupied_masks_.erase(it);
  }
  // A deterministic order for the refills.
  std::sort(freed->begin(), freed->end(),
            [](const Site* a, const Site* b) { return SurfacePoints::Pack(a->key) < SurfacePoints::Pack(b->key); });
}

void SurfaceDistanceLayer::EnableDistances() {
  if (distances_) return;
  distances_ = true;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::uint64_t> keys;
  keys.reserve(sites_.size());
  for (const auto& [packed, site] : sites_) {
    if (site->occupied) keys.push_back(packed);
  }
  std::sort(keys.begin(), keys.end());  // a deterministic order
  for (const std::uint64_t packed : keys) Wave(sites_.at(packed));
  Spread();
  counts_.distance_s += SecondsSince(start);
}

void SurfaceDistanceLayer::Wave(Site* site) {
  if (site->element == nullptr) return;  // no return refreshed into it yet
  ++counts_.waves;
  site->waved = true;
  site->marked = *site->element;
  // Its own voxel (distance 0 wins over any other owner); Spread() goes on from it.
  WorkBlock* block = BlockAt(site->key, true);
  const std::size_t offset = CellOffset(site->key);
  block->sq_distance[offset] = 0;
  block->owner[offset] = site;
  block->Touch(offset);
  ++counts_.cells_claimed;
  Record(site, block);
  Push(site->key, site, block, 0);
}

void SurfaceDistanceLayer::Refill(Site* site) {
  if (!site->waved) return;
  site->waved = false;
  // Release the cells it was nearest to, and queue every neighbouring cell
  // nearest to another occupied voxel for Spread() to go on from.
  std::vector<Eigen::Vector3i> released;
  for (WorkBlock* block : site->blocks) {
    const Eigen::Vector3i first = block->key * kEdge;
    for (int i = 0; i < DistanceField::kBlockCells; ++i) {
      if (block->owner[static_cast<std::size_t>(i)] != site) continue;
      block->owner[static_cast<std::size_t>(i)] = nullptr;
      block->sq_distance[static_cast<std::size_t>(i)] = kFar;
      block->Touch(static_cast<std::size_t>(i));
      released.push_back(first + Eigen::Vector3i(i >> (2 * DistanceField::kBlockShift),
                                                 (i >> DistanceField::kBlockShift) & kMask, i & kMask));
    }
  }
  site->blocks.clear();
  for (const Eigen::Vector3i& cell : released) {
    for (const Eigen::Vector3i& step : kSteps) {
      const Eigen::Vector3i next = cell + step;
      if (!InKeyRange(next)) continue;
      WorkBlock* block = BlockAt(next, false);
      if (block == nullptr) continue;
      const std::size_t offset = CellOffset(next);
      Site* owner = block->owner[offset];
      if (owner != nullptr) Push(next, owner, block, block->sq_distance[offset]);
    }
  }
}

void SurfaceDistanceLayer::Record(Site* site, WorkBlock* block) {
  if (!site->blocks.empty() && site->blocks.back() == block) return;
  if (std::find(site->blocks.begin(), site->blocks.end(), block) == site->blocks.end()) site->blocks.push_back(block);
}

void SurfaceDistanceLayer::Push(const Eigen::Vector3i& cell, Site* site, WorkBlock* block, int sq) {
  // Spread() never pushes beyond reach_^2: buckets_ is not resized while it runs.
  if (buckets_.empty()) buckets_.resize(static_cast<std::size_t>(reach_ * reach_) + 1);
  buckets_[static_cast<std::size_t>(std::max(sq, next_bucket_))].push_back(
      WaveFront{cell, static_cast<std::uint16_t>(sq), site, block});
}

void SurfaceDistanceLayer::Spread() {
  // Dijkstra's order over squared distances (a bucket per value): every
  // queued cell claims its 6 neighbours that are nearer to its owner than to
  // theirs, nearest first, so a cell is claimed about once, by its final
  // owner, instead of once per wave that passes it. A queued cell that has
  // since been claimed by another voxel is skipped (its new owner's entry
  // goes on from it).
  const int reach_sq = reach_ * reach_;
  for (next_bucket_ = 0; static_cast<std::size_t>(next_bucket_) < buckets_.size(); ++next_bucket_) {
    std::vector<WaveFront>& bucket = buckets_[static_cast<std::size_t>(next_bucket_)];
    // Indexed: claims may append to this bucket (a neighbour no farther).
    for (std::size_t head = 0; head < bucket.size(); ++head) {
      const WaveFront front = bucket[head];
      const std::size_t here = CellOffset(front.cell);
      // Skipped when claimed by another voxel since it was queued, or
      // released by a refill (front.site became free, before this Spread):
      // a cell's squared distance only falls during a Spread (a voxel claims
      // a cell only nearer than its owner, and a voxel's distance to a cell
      // is fixed), so a cell still owned has front.sq exactly, and one
      // released went with a site no longer waved.
      if (front.block->sq_distance[here] != front.sq || !front.site->waved) continue;
      const Eigen::Vector3i d = front.cell - front.site->key;
      const int sq_here = front.sq;
      // The 6 neighbours in kSteps' order: +x, -x, +y, -y, +z, -z.
      for (int axis = 0; axis < 3; ++axis) {
        for (int sign = 1; sign >= -1; sign -= 2) {
          const int sq = sq_here + 2 * sign * d[axis] + 1;  // |d + sign e_axis|^2
          if (sq > reach_sq) continue;
          Eigen::Vector3i next = front.cell;
          next[axis] += sign;
          // The same block unless the step crosses its face.
          WorkBlock* block = front.block;
          std::size_t offset = 0;
          const int local = front.cell[axis] & kMask;
          if (local == (sign > 0 ? kMask : 0)) {
            if (!InKeyRange(next)) continue;
            WorkBlock*& across = front.block->neighbors[static_cast<std::size_t>(2 * axis + (sign > 0 ? 0 : 1))];
            if (across == nullptr) across = BlockAt(next, true);
            block = across;
            offset = CellOffset(next);
          } else {
            offset = static_cast<std::size_t>(static_cast<int>(here) + sign * kCellStride[axis]);
          }
          if (!(sq < block->sq_distance[offset])) continue;
          block->sq_distance[offset] = static_cast<std::uint16_t>(sq);
          block->owner[offset] = front.site;
          block->Touch(offset);
          ++counts_.cells_claimed;
          // front.block is already among the site's blocks (it owns front.cell there).
          if (block != front.block) Record(front.site, block);
          Push(next, front.site, block, sq);
        }
      }
    }
    // A large batch (EnableDistances) frees each bucket once done with it:
    // only the wave's front is held at once.
    if (bucket.capacity() > kKeptWaveFronts) {
      std::vector<WaveFront>().swap(bucket);
    } else {
      bucket.clear();
    }
  }
  next_bucket_ = 0;
}

void SurfaceDistanceLayer::MarkIfChanged(Site* site, bool always) {
  if (site->element == nullptr) return;
  if (!always && !Differs(site->marked, *site->element, static_cast<float>(options_.resolution_m))) return;
  site->marked = *site->element;
  // Every cell of its blocks (finding just its own cells costs about as
  // much as recomputing them).
  for (WorkBlock* block : site->blocks) {
    block->dirty = true;
    block->dirty_cells.fill(~std::uint64_t{0});
  }
}

void SurfaceDistanceLayer::Compute(WorkBlock* block, const Eigen::Vector3i& block_key) {
  ++counts_.blocks_computed;
  // Only the cells marked since the last export change: start from its codes.
  auto codes = block->exported ? std::make_shared<DistanceField::Block>(*block->exported)
                               : std::make_shared<DistanceField::Block>(
                                     static_cast<std::size_t>(DistanceField::kBlockCells), DistanceField::kMaxSteps);
  // Cell centres per axis, as Centre() computes them.
  std::array<Eigen::Vector3f, kEdge> axis_centers;
  for (int i = 0; i < kEdge; ++i) {
    axis_centers[static_cast<std::size_t>(i)] = Center(block_key * kEdge + Eigen::Vector3i::Constant(i));
  }
  for (std::size_t word = 0; word < block->dirty_cells.size(); ++word) {
    for (std::uint64_t bits = block->dirty_cells[word]; bits != 0; bits &= bits - 1) {
      const std::size_t offset = word * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
      const Site* owner = block->owner[offset];
      if (owner == nullptr) {
        (*codes)[offset] = DistanceField::kMaxSteps;
        continue;
      }
      const int x = static_cast<int>(offset >> (2 * DistanceField::kBlockShift));
      const int y = static_cast<int>((offset >> DistanceField::kBlockShift) & kMask);
      const int z = static_cast<int>(offset & kMask);
      const Eigen::Vector3f center(axis_centers[static_cast<std::size_t>(x)].x(),
                                   axis_centers[static_cast<std::size_t>(y)].y(),
                                   axis_centers[static_cast<std::size_t>(z)].z());
      (*codes)[offset] = DistanceField::Quantise(surfaces_.SignedDistance(*owner->element, center), clamp_m_);
    }
  }
  block->dirty_cells.fill(0);
  const bool any =
      std::any_of(codes->begin(), codes->end(), [](std::uint16_t code) { return code != DistanceField::kMaxSteps; });
  block->exported = any ? std::move(codes) : nullptr;
  block->dirty = false;
}

std::shared_ptr<const DistanceField> SurfaceDistanceLayer::Export(const Eigen::Vector3f& center_map,
                                                                  double half_range_m, std::uint64_t sequence) {
  const auto start = std::chrono::steady_clock::now();
  for (auto it = blocks_.begin(); it != blocks_.end(); ++it) {
    if (it->second->dirty) Compute(it->second.get(), it->second->key);
  }
  const auto computed = std::chrono::steady_clock::now();
  counts_.distance_s += std::chrono::duration<double>(computed - start).count();
  Eigen::Vector3i low = block_min_;
  Eigen::Vector3i high = block_max_;
  if (half_range_m > 0.0) {
    const Eigen::Vector3f reach = Eigen::Vector3f::Constant(static_cast<float>(half_range_m));
    const double to_key = 1.0 / options_.resolution_m;
    const Eigen::Vector3d a = ((center_map - reach).cast<double>() * to_key).array().floor() + kKeyOffset;
    const Eigen::Vector3d b = ((center_map + reach).cast<double>() * to_key).array().floor() + kKeyOffset;
    low = low.cwiseMax(a.cwiseMax(0.0).cwiseMin(kMaxKey).cast<int>() / kEdge);
    high = high.cwiseMin(b.cwiseMax(0.0).cwiseMin(kMaxKey).cast<int>() / kEdge);
  }
  const Eigen::Vector3i dims = (high - low).array() + 1;
  if ((dims.array() <= 0).any()) {
    counts_.export_s += SecondsSince(computed);
    return std::make_shared<const DistanceField>(clamp_m_, sequence);
  }
  std::vector<std::shared_ptr<const DistanceField::Block>> table(
      static_cast<std::size_t>(dims.x()) * static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(dims.z()));
  for (const auto& [packed, block] : blocks_) {
    const Eigen::Vector3i b = Unpack(packed) - low;
    if ((b.array() < 0).any() || (b.array() >= dims.array()).any()) continue;
    table[(static_cast<std::size_t>(b.x()) * static_cast<std::size_t>(dims.y()) + static_cast<std::size_t>(b.y())) *
              static_cast<std::size_t>(dims.z()) +
          static_cast<std::size_t>(b.z())] = block->exported;
  }
  const Eigen::Vector3f origin =
      ((low.cast<double>().array() * kEdge - kKeyOffset) * options_.resolution_m).cast<float>().matrix();
  auto field = std::make_shared<const DistanceField>(origin, dims, static_cast<float>(options_.resolution_m), clamp_m_,
                                                     std::move(table), sequence);
  counts_.export_s += SecondsSince(computed);
  return field;
}

std::vector<Eigen::Vector3f> SurfaceDistanceLayer::VoxelCenters() const {
  std::vector<std::uint64_t> keys;
  keys.reserve(sites_.size());
  for (const auto& [packed, site] : sites_) {
    if (site->occupied) keys.push_back(packed);
  }
  std::sort(keys.begin(), keys.end());  // a deterministic order
  std::vector<Eigen::Vector3f> centers;
  centers.reserve(keys.size());
  for (const std::uint64_t packed : keys) centers.push_back(Center(Unpack(packed)));
  return centers;
}

std::vector<Eigen::Vector3f> SurfaceDistanceLayer::SurfaceMeans() const {
  std::vector<std::pair<std::uint64_t, const SurfacePoints::Element*>> elements;
  elements.reserve(occupied_);
  for (const auto& [packed, site] : sites_) {
    if (site->occupied && site->element != nullptr) elements.emplace_back(packed, site->element);
  }
  std::sort(elements.begin(), elements.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::Vector3f> out;
  out.reserve(elements.size());
  const float resolution = static_cast<float>(options_.resolution_m);
  for (const auto& [packed, element] : elements) {
    const int half = static_cast<int>(element->scale) / 2;
    if (half == 0 || !element->planar) {
      out.push_back(element->mean_m);
      continue;
    }
    // A coarse cell's plane, sampled a voxel apart as its own voxels would
    // be: the loop-closure matcher reads retired submaps at that density.
    const Eigen::Vector3f& n = element->normal;
    int least = 0;
    n.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3f u = n.cross(Eigen::Vector3f::Unit(least)).normalized();
    const Eigen::Vector3f v = n.cross(u);
    for (int i = -half; i <= half; ++i) {
      for (int j = -half; j <= half; ++j) {
        out.push_back(element->mean_m + (static_cast<float>(i) * u + static_cast<float>(j) * v) * resolution);
      }
    }
  }
  return out;
}

SurfaceDistanceCounts SurfaceDistanceLayer::counts() const {
  SurfaceDistanceCounts counts = counts_;
  counts.elements = surfaces_.size();
  counts.occupied = occupied_;
  counts.blocks = blocks_.size();
  return counts;
}

}  // namespace unimap::map
