#pragma once
// Synthetic geometry and a brute-force distance reference for the map tests.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceField.hpp"

namespace unimap::map::test {

// Points on the parallelogram corner + s * edge_u + t * edge_v, s, t in
// [0, 1], spaced at most spacing_m apart.
inline std::vector<Eigen::Vector3f> SampleRectangle(const Eigen::Vector3f& corner, const Eigen::Vector3f& edge_u,
                                                    const Eigen::Vector3f& edge_v, float spacing_m) {
  const int nu = std::max(1, static_cast<int>(std::ceil(edge_u.norm() / spacing_m)));
  const int nv = std::max(1, static_cast<int>(std::ceil(edge_v.norm() / spacing_m)));
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i <= nu; ++i) {
    for (int j = 0; j <= nv; ++j) {
      points.push_back(corner + edge_u * (static_cast<float>(i) / static_cast<float>(nu)) +
                       edge_v * (static_cast<float>(j) / static_cast<float>(nv)));
    }
  }
  return points;
}

// Points on the six faces of the box [low, high].
inline std::vector<Eigen::Vector3f> SampleBoxSurface(const Eigen::Vector3f& low, const Eigen::Vector3f& high,
                                                     float spacing_m) {
  std::vector<Eigen::Vector3f> points;
  const Eigen::Vector3f size = high - low;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3;
    const int b = (axis + 2) % 3;
    Eigen::Vector3f edge_a = Eigen::Vector3f::Zero();
    Eigen::Vector3f edge_b = Eigen::Vector3f::Zero();
    edge_a[a] = size[a];
    edge_b[b] = size[b];
    for (const float face : {low[axis], high[axis]}) {
      Eigen::Vector3f corner = low;
      corner[axis] = face;
      const std::vector<Eigen::Vector3f> side = SampleRectangle(corner, edge_a, edge_b, spacing_m);
      points.insert(points.end(), side.begin(), side.end());
    }
  }
  return points;
}

inline void Append(std::vector<Eigen::Vector3f>* to, const std::vector<Eigen::Vector3f>& from) {
  to->insert(to->end(), from.begin(), from.end());
}

// Distance from p to the nearest of centres, clamped at clamp_m.
inline float BruteForceDistance(const std::vector<Eigen::Vector3f>& centers, const Eigen::Vector3f& p, float clamp_m) {
  float best_sq = clamp_m * clamp_m;
  const float px = p.x();
  const float py = p.y();
  const float pz = p.z();
  for (const Eigen::Vector3f& c : centers) {  // plain arithmetic: fast in debug builds too
    const float dx = c.x() - px;
    const float dy = c.y() - py;
    const float dz = c.z() - pz;
    best_sq = std::min(best_sq, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(best_sq);
}

// The centres that can lie within clamp_m of the box [low, high].
inline std::vector<Eigen::Vector3f> CentersNear(const std::vector<Eigen::Vector3f>& centers, const Eigen::Vector3f& low,
                                                const Eigen::Vector3f& high, float clamp_m) {
  std::vector<Eigen::Vector3f> near;
  for (const Eigen::Vector3f& c : centers) {
    if ((c.array() >= low.array() - clamp_m).all() && (c.array() <= high.array() + clamp_m).all()) {
      near.push_back(c);
    }
  }
  return near;
}

// Centre of the field voxel containing p (p inside the field's box).
inline Eigen::Vector3f VoxelCenterOf(const DistanceField& field, const Eigen::Vector3f& p) {
  const Eigen::Vector3f f = (p - field.origin()) / field.resolution();
  const Eigen::Vector3i cell = f.array().floor().cast<int>();
  return field.CellCenter(cell.cwiseMax(0).cwiseMin(field.dims() - Eigen::Vector3i::Ones()));
}

// Uniform random points in [low, high].
inline std::vector<Eigen::Vector3f> RandomPoints(const Eigen::Vector3f& low, const Eigen::Vector3f& high, int count,
                                                 std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Eigen::Vector3f> points(static_cast<std::size_t>(count));
  for (Eigen::Vector3f& p : points) {
    p = low + Eigen::Vector3f(unit(rng), unit(rng), unit(rng)).cwiseProduct(high - low);
  }
  return points;
}

// Largest |field - brute force| over queries, the brute force evaluated at
// the centre of each query's voxel (what the field stores).
inline float MaxVoxelCenterError(const DistanceField& field, const std::vector<Eigen::Vector3f>& occupied_centers,
                                 const std::vector<Eigen::Vector3f>& queries) {
  float worst = 0.0f;
  for (const Eigen::Vector3f& p : queries) {
    const float truth = BruteForceDistance(occupied_centers, VoxelCenterOf(field, p), field.clamp());
    worst = std::max(worst, std::abs(field.Distance(p) - truth));
  }
  return worst;
}

}  // namespace unimap::map::test
