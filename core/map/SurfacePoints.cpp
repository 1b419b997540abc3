#include "map/SurfacePoints.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace unimap::map {

namespace {

// Returns (pooled over the neighbourhood) needed before a plane is fitted.
constexpr float kMinPlaneWeight = 6.0f;
// Planar: the second principal spread is at least this (voxels, std dev) ...
constexpr float kMinSpread = 0.1f;
// ... and the smallest variance at most this fraction of the second.
constexpr float kMaxFlatness = 0.3f;
// Oriented: mean cosine between the normal and the view directions.
constexpr float kMinViewCosine = 0.2f;

// Sets element's normal (and planar, oriented) from the scatter of the
// returns about their mean and their mean unit vector towards the sensor:
// - a plane (two principal spreads of at least min_spread_m, the third at
//   most kMaxFlatness of the second): the smallest principal axis, turned
//   towards the sensor when the mean view cosine is at least kMinViewCosine;
// - a line (one scan line across a sparsely scanned surface): the surface
//   contains it, so its normal is perpendicular to it; the one closest to
//   the view direction is taken (off by the incidence angle across the
//   line), when that direction is known (its part across the line is at
//   least kMinViewCosine);
// - anything else (a blob, a corner, rough or two-sided): none.
void FitPlane(const Eigen::Matrix3f& scatter, const Eigen::Vector3f& mean_view, float min_spread_m,
              SurfacePoints::Element* element) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> eigen;
  eigen.computeDirect(scatter);  // eigenvalues ascending
  const Eigen::Vector3f lambda = eigen.eigenvalues();
  const float min_variance = min_spread_m * min_spread_m;
  if (lambda[1] >= min_variance && lambda[0] <= kMaxFlatness * lambda[1]) {
    element->planar = true;
    element->normal = eigen.eigenvectors().col(0).normalized();
    const float view_cosine = element->normal.dot(mean_view);
    if (std::abs(view_cosine) >= kMinViewCosine) {
      element->oriented = true;
      if (view_cosine < 0.0f) element->normal = -element->normal;
    }
    return;
  }
  if (lambda[2] < min_variance || lambda[1] >= min_variance) return;  // no line
  const Eigen::Vector3f line = eigen.eigenvectors().col(2).normalized();
  const Eigen::Vector3f across = mean_view - mean_view.dot(line) * line;
  if (across.norm() < kMinViewCosine) return;
  element->planar = true;
  element->oriented = true;
  element->normal = across.normalized();
}

}  // namespace

SurfacePoints::SurfacePoints(double resolution_m, bool signed_distances, float patch_radius_voxels)
    : resolution_m_(static_cast<float>(resolution_m)),
      signed_(signed_distances),
      patch_radius_m_(patch_radius_voxels * resolution_m_),
      patch_radius_sq_m2_(patch_radius_m_ * patch_radius_m_) {}

SurfacePoints::Slot SurfacePoints::Add(std::uint64_t key, const Eigen::Vector3f& voxel_center_map,
                                       const Eigen::Vector3f& p_map, const Eigen::Vector3f* sensor_map, float scale) {
  if (key != last_key_) {
    const auto it = index_.find(key);
    if (it != index_.end()) {
      last_slot_ = it->second;
    } else {
      if (free_.empty()) {
        last_slot_ = static_cast<std::uint32_t>(store_.size());
        store_.emplace_back();
      } else {
        last_slot_ = free_.back();
        free_.pop_back();
        store_[last_slot_] = Entry{};
      }
      index_.emplace(key, last_slot_);
    }
    last_key_ = key;
  }
  Entry& entry = store_[last_slot_];
  if (entry.weight >= kMaxWeight) {
    // Exponential average: the moments keep the weight of kMaxWeight returns.
    const float keep = (kMaxWeight - 1.0f) / kMaxWeight;
    entry.weight = kMaxWeight - 1.0f;
    entry.sum *= keep;
    entry.sum_sq *= keep;
    entry.sum_view *= keep;
  }
  const Eigen::Vector3f d = p_map - voxel_center_map;
  entry.scale = std::max(entry.scale, scale);
  entry.weight += 1.0f;
  entry.adds_since_fit += 1.0f;
  entry.sum += d;
  entry.sum_sq += (Eigen::Matrix<float, 6, 1>() << d.x() * d.x(), d.x() * d.y(), d.x() * d.z(), d.y() * d.y(),
                   d.y() * d.z(), d.z() * d.z())
                      .finished();
  if (sensor_map != nullptr) {
    const Eigen::Vector3f view = *sensor_map - p_map;
    const float length = view.norm();
    if (length > 0.0f) entry.sum_view += view / length;
  }
  return last_slot_;
}

SurfacePoints::Entry SurfacePoints::PooledMoments(std::uint64_t key, int step) const {
  const int kx = static_cast<int>((key >> 32) & 0xffff);
  const int ky = static_cast<int>((key >> 16) & 0xffff);
  const int kz = static_cast<int>(key & 0xffff);
  Entry pooled;
  for (int dx = -step; dx <= step; dx += step) {
    for (int dy = -step; dy <= step; dy += step) {
      for (int dz = -step; dz <= step; dz += step) {
        const Eigen::Vector3i neighbor(kx + dx, ky + dy, kz + dz);
        if ((neighbor.array() < 0).any() || (neighbor.array() > 0xffff).any()) continue;
        const Entry* found = Lookup(Pack(neighbor));
        if (found == nullptr) continue;
        const Entry& n = *found;
        // Shift the neighbour's moments by its centre offset o:
        // sum d' = sum d + w o, sum d' d'^T = sum d d^T + o sum^T + sum o^T + w o o^T.
        const Eigen::Vector3f o =
            Eigen::Vector3f(static_cast<float>(dx), static_cast<float>(dy), static_cast<float>(dz)) * resolution_m_;
        const Eigen::Vector3f s = n.sum + n.weight * o;
        pooled.weight += n.weight;
        pooled.sum += s;
        // o s^T + s o^T - w o o^T, with s the shifted sum, equals the middle terms.
        const Eigen::Matrix3f cross = o * s.transpose() + s * o.transpose() - n.weight * o * o.transpose();
        pooled.sum_sq += n.sum_sq + (Eigen::Matrix<float, 6, 1>() << cross(0, 0), cross(0, 1), cross(0, 2), cross(1, 1),
                                     cross(1, 2), cross(2, 2))
                                        .finished();
        pooled.sum_view += n.sum_view;
      }
    }
  }
  return pooled;
}

const SurfacePoints::Element* SurfacePoints::Refresh(std::uint64_t key, const Eigen::Vector3f& voxel_center_map) {
  Entry* found = Lookup(key);
  return found == nullptr ? nullptr : RefreshEntry(found, key, voxel_center_map);
}

const SurfacePoints::Element* SurfacePoints::Refresh(Slot slot, std::uint64_t key,
                                                     const Eigen::Vector3f& voxel_center_map) {
  return RefreshEntry(&store_[slot], key, voxel_center_map);
}

const SurfacePoints::Element* SurfacePoints::RefreshEntry(Entry* found, std::uint64_t key,
                                                          const Eigen::Vector3f& voxel_center_map) {
  Entry& entry = *found;
  entry.element.mean_m = voxel_center_map + entry.sum / entry.weight;
  entry.element.scale = entry.scale;
  const float refit_after = entry.weight >= kMaxWeight ? kMaxWeight : kRefitFraction * entry.weight;
  const bool refit = !entry.has_element || entry.adds_since_fit >= refit_after;
  entry.has_element = true;
  if (!refit) return &entry.element;
  entry.adds_since_fit = 0.0f;
  Element& element = entry.element;
  element.planar = false;
  element.oriented = false;
  element.normal.setZero();
  // A coarse cell pools the cells around it, as a voxel its neighbours.
  const Entry pooled = PooledMoments(key, static_cast<int>(entry.scale));
  if (pooled.weight < kMinPlaneWeight) return &entry.element;
  // Scatter about the pooled mean: E[d d^T] - mean mean^T.
  const Eigen::Vector3f mean = pooled.sum / pooled.weight;
  const Eigen::Matrix<float, 6, 1> m = pooled.sum_sq / pooled.weight;
  Eigen::Matrix3f scatter;
  scatter << m[0], m[1], m[2], m[1], m[3], m[4], m[2], m[4], m[5];
  scatter -= mean * mean.transpose();
  FitPlane(scatter, pooled.sum_view / pooled.weight, kMinSpread * resolution_m_, &element);
  return &entry.element;
}

void SurfacePoints::Erase(std::uint64_t key) {
  const auto it = index_.find(key);
  if (it == index_.end()) return;
  free_.push_back(it->second);
  store_[it->second] = Entry{};
  index_.erase(it);
  if (key == last_key_) last_key_ = ~std::uint64_t{0};
}

SurfacePoints::Entry* SurfacePoints::Lookup(std::uint64_t key) {
  const auto it = index_.find(key);
  return it == index_.end() ? nullptr : &store_[it->second];
}

const SurfacePoints::Entry* SurfacePoints::Lookup(std::uint64_t key) const {
  const auto it = index_.find(key);
  return it == index_.end() ? nullptr : &store_[it->second];
}

const SurfacePoints::Element* SurfacePoints::Find(std::uint64_t key) const {
  const Entry* entry = Lookup(key);
  if (entry == nullptr || !entry->has_element) return nullptr;
  return &entry->element;
}

void SurfacePoints::ForEach(const std::function<void(std::uint64_t, const Element&)>& visit) const {
  for (const auto& [key, slot] : index_) {
    const Entry& entry = store_[slot];
    if (entry.has_element) visit(key, entry.element);
  }
}

std::size_t SurfacePoints::MemoryBytes() const {
  // The store's entries (erased slots included) plus the index's buckets (key, slot, hash bookkeeping).
  return store_.size() * sizeof(Entry) + free_.capacity() * sizeof(std::uint32_t) +
         index_.bucket_count() * (sizeof(std::uint64_t) + 2 * sizeof(std::uint32_t));
}

}  // namespace unimap::map
