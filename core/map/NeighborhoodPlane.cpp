#include "map/NeighborhoodPlane.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace unimap::map {

bool NeighborhoodPlaneOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  if (radius_cells < 1 || radius_cells > 8) {
    *why = "radius_cells must be in [1, 8]";
    return false;
  }
  if (min_cells < 3) {
    *why = "min_cells must be >= 3";
    return false;
  }
  if (!(max_thickness_ratio > 0.0 && max_thickness_ratio < 1.0) ||
      !(min_spread_ratio > 0.0 && min_spread_ratio <= 1.0)) {
    *why = "max_thickness_ratio must be in (0, 1) and min_spread_ratio in (0, 1]";
    return false;
  }
  return true;
}

NeighborhoodPlane FitNeighborhoodPlane(const DistanceField& field, const Eigen::Vector3f& p_map,
                                       const NeighborhoodPlaneOptions& options) {
  NeighborhoodPlane out;
  if (field.CellCount() == 0 || !p_map.allFinite()) return out;
  const float surface_m = 0.5f * field.resolution();
  const Eigen::Vector3i center = ((p_map - field.origin()) / field.resolution()).array().floor().cast<int>();
  const int r = options.radius_cells;
  // Moments about the centre of the point's cell (small numbers, no cancellation).
  const Eigen::Vector3d reference = field.CellCenter(center).cast<double>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_sq = Eigen::Matrix3d::Zero();
  int count = 0;
  for (int dx = -r; dx <= r; ++dx) {
    for (int dy = -r; dy <= r; ++dy) {
      for (int dz = -r; dz <= r; ++dz) {
        const Eigen::Vector3i cell = center + Eigen::Vector3i(dx, dy, dz);
        if (!(field.CellDistance(cell) <= surface_m)) continue;  // outside the grid reads clamp()
        const Eigen::Vector3d x = field.CellCenter(cell).cast<double>() - reference;
        sum += x;
        sum_sq += x * x.transpose();
        ++count;
      }
    }
  }
  if (count < options.min_cells) return out;
  const Eigen::Vector3d mean = sum / count;
  const Eigen::Matrix3d covariance = sum_sq / count - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Eigen::Vector3d& l = eigen.eigenvalues();  // ascending
  if (l(1) < options.min_spread_ratio * l(2)) {
    out.shape = NeighborhoodShape::kLinear;
    return out;
  }
  if (l(0) > options.max_thickness_ratio * l(1)) {
    out.shape = NeighborhoodShape::kVolumetric;
    return out;
  }
  const Eigen::Vector3d normal = eigen.eigenvectors().col(0).normalized();
  out.shape = NeighborhoodShape::kPlanar;
  out.normal_map = normal.cast<float>();
  out.offset_m = static_cast<float>(-normal.dot(mean + reference));
  return out;
}

}  // namespace unimap::map
