#include "matching/VoxelDownsampler.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

namespace unimap::matching {

std::uint64_t VoxelKey(const Eigen::Vector3f& p, double inv_voxel) {
  const auto cell = [&](float v) { return static_cast<int>(std::floor(v * inv_voxel)); };
  return VoxelCellKey(Eigen::Vector3i(cell(p.x()), cell(p.y()), cell(p.z())));
}

std::vector<std::size_t> VoxelFirstIndices(const std::vector<Eigen::Vector3f>& points, double voxel_m) {
  std::vector<std::size_t> kept;
  if (voxel_m <= 0.0) {
    kept.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) kept[i] = i;
    return kept;
  }
  const double inv_voxel = 1.0 / voxel_m;
  VoxelKeySet seen;
  // Sized for a few returns per voxel (it grows if there are fewer): a
  // table for every point is mostly empty and slower to probe.
  seen.reserve(points.size() / 4 + 16);
  // A scan lists its returns in firing order: neighbours mostly share a
  // voxel, and a key equal to the previous point's is not new (one set
  // look-up saved; the same indices). Keys use 63 bits: none is ~0.
  std::uint64_t previous = ~std::uint64_t{0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint64_t key = VoxelKey(points[i], inv_voxel);
    if (key == previous) continue;
    previous = key;
    if (seen.insert(key).second) kept.push_back(i);
  }
  return kept;
}

std::vector<Eigen::Vector3f> VoxelDownsample(const std::vector<Eigen::Vector3f>& points, double voxel_m, int max_points,
                                             std::uint64_t seed) {
  std::vector<Eigen::Vector3f> kept;
  if (voxel_m > 0.0) {
    const std::vector<std::size_t> first = VoxelFirstIndices(points, voxel_m);
    kept.reserve(first.size());
    for (const std::size_t i : first) kept.push_back(points[i]);
  } else {
    kept = points;
  }
  if (max_points > 0 && static_cast<int>(kept.size()) > max_points) {
    // Partial Fisher-Yates: the first max_points entries become a uniform sample.
    std::mt19937_64 rng(seed);
    for (int i = 0; i < max_points; ++i) {
      std::uniform_int_distribution<std::size_t> pick(static_cast<std::size_t>(i), kept.size() - 1);
      std::swap(kept[static_cast<std::size_t>(i)], kept[pick(rng)]);
    }
    kept.resize(static_cast<std::size_t>(max_points));
  }
  return kept;
}

std::vector<Eigen::Vector3f> VoxelCentroids(const std::vector<Eigen::Vector3f>& points, double voxel_m) {
  if (!(voxel_m > 0.0)) return points;
  const double inv_voxel = 1.0 / voxel_m;
  std::unordered_map<std::uint64_t, std::size_t> index;  // voxel -> its slot
  index.reserve(points.size());
  std::vector<Eigen::Vector3d> sums;
  std::vector<int> counts;
  for (const auto& p : points) {
    const auto [it, fresh] = index.try_emplace(VoxelKey(p, inv_voxel), sums.size());
    if (fresh) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      counts.push_back(0);
    }
    sums[it->second] += p.cast<double>();
    ++counts[it->second];
  }
  std::vector<Eigen::Vector3f> centroids(sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) centroids[i] = (sums[i] / counts[i]).cast<float>();
  return centroids;
}

}  // namespace unimap::matching
