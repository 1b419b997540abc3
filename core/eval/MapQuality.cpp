#include "eval/MapQuality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Eigenvalues>

namespace unimap::eval {
namespace {

// Points sorted into cubic cells of the neighbourhood radius, so that a
// point's neighbours are in its cell and the 26 around it.
class CellIndex {
 public:
  CellIndex(const std::vector<Eigen::Vector3f>& points, double cell_m)
      : points_(points), inv_cell_(1.0 / cell_m), order_(points.size()) {
    std::vector<std::int64_t> keys(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) keys[i] = Key(CellOf(points[i]));
    std::iota(order_.begin(), order_.end(), 0);
    std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    for (std::size_t k = 0; k < order_.size();) {
      std::size_t end = k;
      while (end < order_.size() && keys[order_[end]] == keys[order_[k]]) ++end;
      ranges_.emplace(keys[order_[k]], std::make_pair(k, end));
      k = end;
    }
  }

  // Calls visit(point) for every point within radius_m of p.
  template <class Visit>
  void ForNeighbors(const Eigen::Vector3f& p, double radius_m, Visit&& visit) const {
    const Eigen::Vector3i c = CellOf(p);
    const float r2 = static_cast<float>(radius_m * radius_m);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = ranges_.find(Key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == ranges_.end()) continue;
          for (std::size_t k = it->second.first; k < it->second.second; ++k) {
            const Eigen::Vector3f& q = points_[order_[k]];
            if ((q - p).squaredNorm() <= r2) visit(q);
          }
        }
      }
    }
  }

 private:
  Eigen::Vector3i CellOf(const Eigen::Vector3f& p) const {
    return (p.cast<double>() * inv_cell_).array().floor().cast<int>();
  }
  // 21 bits per axis (cells within +-1e6 of the origin).
  static std::int64_t Key(const Eigen::Vector3i& c) {
    const auto part = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & ((1 << 21) - 1); };
    return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
  }

  const std::vector<Eigen::Vector3f>& points_;
  double inv_cell_;
  std::vector<std::size_t> order_;
  std::unordered_map<std::int64_t, std::pair<std::size_t, std::size_t>> ranges_;
};

}  // namespace

bool MapQualityOptions::IsValid(std::string* why) const {
  std::string local;
  if (why == nullptr) why = &local;
  if (!(radius_m > 0.0) || !std::isfinite(radius_m)) {
    *why = "radius_m must be positive";
    return false;
  }
  if (min_neighbors < 4) {
    *why = "min_neighbors must be at least 4 (a covariance of 3 dimensions)";
    return false;
  }
  if (!(planar_ratio > 0.0 && planar_ratio < 1.0) || !(min_variance_m2 > 0.0)) {
    *why = "planar_ratio must be in (0, 1) and min_variance_m2 positive";
    return false;
  }
  return true;
}

MapQuality ComputeMapQuality(const std::vector<Eigen::Vector3f>& points_map, const MapQualityOptions& options) {
  if (std::string why; !options.IsValid(&why)) throw std::invalid_argument("map quality options: " + why);
  MapQuality quality;
  quality.points = points_map.size();
  if (points_map.empty()) return quality;
  const CellIndex index(points_map, options.radius_m);
  const std::size_t stride =
      options.max_points == 0
          ? 1
          : std::max<std::size_t>(1, (points_map.size() + options.max_points - 1) / options.max_points);
  const double two_pi_e = 2.0 * M_PI * std::exp(1.0);
  double entropy_sum = 0.0;
  double plane_variance_sum = 0.0;
  std::size_t planar = 0;
  for (std::size_t i = 0; i < points_map.size(); i += stride) {
    // Sigma = E[q q^T] - mu mu^T, accumulated about the point for precision.
    const Eigen::Vector3d p = points_map[i].cast<double>();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    int n = 0;
    index.ForNeighbors(points_map[i], options.radius_m, [&](const Eigen::Vector3f& q) {
      const Eigen::Vector3d d = q.cast<double>() - p;
      sum += d;
      outer += d * d.transpose();
      ++n;
    });
    if (n < options.min_neighbors) continue;
    const Eigen::Vector3d mean = sum / n;
    const Eigen::Matrix3d sigma = outer / n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(sigma, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d lambda = solver.eigenvalues().cwiseMax(options.min_variance_m2);  // ascending
    entropy_sum += 0.5 * std::log(two_pi_e * two_pi_e * two_pi_e * lambda.prod());
    plane_variance_sum += lambda(0);
    if (lambda(0) <= options.planar_ratio * lambda(1)) ++planar;
    ++quality.evaluated;
  }
  if (quality.evaluated > 0) {
    const double n = static_cast<double>(quality.evaluated);
    quality.mean_map_entropy = entropy_sum / n;
    quality.mean_plane_variance_m2 = plane_variance_sum / n;
    quality.planar_share = static_cast<double>(planar) / n;
  }
  return quality;
}

}  // namespace unimap::eval
