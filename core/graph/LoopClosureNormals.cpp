#include "graph/LoopClosureNormals.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Eigenvalues>

#include "matching/VoxelDownsampler.hpp"

namespace unimap::graph {

namespace {

// Scatter sums of the points in one cube (relative to a reference point,
// for precision).
struct Moments {
  double count = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
};

}  // namespace

std::vector<Eigen::Vector3f> LoopClosureNormals(const std::vector<Eigen::Vector3f>& points, double cell_m,
                                                double planarity_ratio) {
  std::vector<Eigen::Vector3f> normals(points.size(), Eigen::Vector3f::Zero());
  if (points.empty()) return normals;
  const Eigen::Vector3d reference = points.front().cast<double>();
  const double inverse = 1.0 / cell_m;
  std::unordered_map<std::uint64_t, Moments> cubes;
  cubes.reserve(points.size() / 4 + 16);
  std::vector<std::uint64_t> keys(points.size());
  std::vector<Eigen::Vector3i> cells(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = points[i].cast<double>() - reference;
    cells[i] =
        Eigen::Vector3i(static_cast<int>(std::floor(p.x() * inverse)), static_cast<int>(std::floor(p.y() * inverse)),
                        static_cast<int>(std::floor(p.z() * inverse)));
    keys[i] = matching::VoxelCellKey(cells[i]);
    Moments& m = cubes[keys[i]];
    m.count += 1.0;
    m.sum += p;
    m.outer += p * p.transpose();
  }
  // One plane per cube from its and its neighbours' points.
  std::unordered_map<std::uint64_t, Eigen::Vector3f> plane_of;
  plane_of.reserve(cubes.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (plane_of.count(keys[i]) != 0) continue;
    Moments pooled;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cubes.find(matching::VoxelCellKey(cells[i] + Eigen::Vector3i(dx, dy, dz)));
          if (it == cubes.end()) continue;
          pooled.count += it->second.count;
          pooled.sum += it->second.sum;
          pooled.outer += it->second.outer;
        }
      }
    }
    Eigen::Vector3f normal = Eigen::Vector3f::Zero();
    if (pooled.count >= 5.0) {
      const Eigen::Vector3d mean = pooled.sum / pooled.count;
      const Eigen::Matrix3d scatter = pooled.outer / pooled.count - mean * mean.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
      if (eigen.info() == Eigen::Success && eigen.eigenvalues()(0) <= planarity_ratio * eigen.eigenvalues()(1)) {
        normal = eigen.eigenvectors().col(0).cast<float>().normalized();
      }
    }
    plane_of.emplace(keys[i], normal);
  }
  for (std::size_t i = 0; i < points.size(); ++i) normals[i] = plane_of[keys[i]];
  return normals;
}

}  // namespace unimap::graph
