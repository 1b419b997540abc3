#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace unimap::calibration {

// Points binned in cubes of a given edge for radius searches (a radius up to
// the edge finds every point within it by looking at the 27 cubes around).
// The cubes are a sorted array of (cube, point index): deterministic, no
// hashing, 12 bytes per point.
class PointGrid {
 public:
  // points: kept by reference, must outlive the grid; edge_m > 0.
  PointGrid(const std::vector<Eigen::Vector3f>& points, double edge_m);

  // Calls visit(index) for every point within radius_m (<= the edge) of
  // centre, in a fixed order.
  template <typename Visit>
  void ForEachWithin(const Eigen::Vector3f& centre, double radius_m, Visit&& visit) const {
    const Eigen::Vector3i c = Cube(centre);
    const float r2 = static_cast<float>(radius_m * radius_m);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const auto [first, last] = Range(Pack(c + Eigen::Vector3i(dx, dy, dz)));
          for (std::size_t k = first; k < last; ++k) {
            const std::uint32_t index = cells_[k].second;
            if ((points_[index] - centre).squaredNorm() <= r2) visit(index);
          }
        }
      }
    }
  }

 private:
  Eigen::Vector3i Cube(const Eigen::Vector3f& p) const;
  static std::uint64_t Pack(const Eigen::Vector3i& cube);
  // The entries of cells_ in cube packed: [first, last).
  std::pair<std::size_t, std::size_t> Range(std::uint64_t packed) const;

  const std::vector<Eigen::Vector3f>& points_;
  double inverse_edge_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells_;  // sorted by cube
};

}  // namespace unimap::calibration
