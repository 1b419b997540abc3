#include "calibration/Neighbourhoods.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/PlaneFit.hpp"
#include "calibration/PointGrid.hpp"

namespace unimap::calibration {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// Evenly chosen: at most count of items.
std::vector<std::uint32_t> Evenly(const std::vector<std::uint32_t>& items, std::size_t count) {
  count = std::min(count, items.size());
  std::vector<std::uint32_t> chosen;
  for (std::size_t c = 0; c < count; ++c) chosen.push_back(items[c * items.size() / count]);
  return chosen;
}

}  // namespace

std::vector<Neighbourhood> ChooseNeighbourhoods(const std::vector<CalibrationReturn>& returns,
                                                const Eigen::Isometry3d& X, const CalibrationOptions& o,
                                                double gate_m) {
  const std::vector<Eigen::Vector3f> world = ExtrinsicCalibrator::Assemble(returns, X);
  const PointGrid grid(world, o.neighbourhood_radius_m);
  const std::size_t stride =
      std::max<std::size_t>(1, (returns.size() + o.max_neighbourhoods - 1) / o.max_neighbourhoods);
  const float max_cos_half = static_cast<float>(std::cos(0.5 * o.min_view_angle_deg * kDegToRad));
  const float min_distance2 = static_cast<float>(o.min_view_distance_m * o.min_view_distance_m);
  const double max_plane_variance = std::pow(o.max_plane_sigmas * o.sigma_m, 2);
  std::vector<Neighbourhood> chosen;
  std::vector<std::uint32_t> same, other;
  std::vector<Eigen::Vector3d> plane_points;
  for (std::size_t i = 0; i < returns.size(); i += stride) {
    const CalibrationReturn& centre = returns[i];
    same.clear();
    other.clear();
    grid.ForEachWithin(world[i], o.neighbourhood_radius_m, [&](std::uint32_t k) {
      const CalibrationReturn& r = returns[k];
      const bool another_view = std::abs(r.q_world_lidar.dot(centre.q_world_lidar)) <= max_cos_half ||
                                (r.t_world_lidar - centre.t_world_lidar).squaredNorm() >= min_distance2;
      (another_view ? other : same).push_back(k);
    });
    if (static_cast<int>(other.size()) < o.min_neighbours) continue;
    Neighbourhood n;
    n.plane = Evenly(other, static_cast<std::size_t>(o.max_neighbours));
    plane_points.clear();
    for (const std::uint32_t k : n.plane) plane_points.push_back(world[k].cast<double>());
    const PlaneFit fit = FitPlane(plane_points);
    const Eigen::Vector3d& lambda = fit.eigenvalues;  // ascending
    if (!(lambda(0) <= o.planar_ratio * lambda(1)) || !(lambda(1) >= o.min_spread_ratio * lambda(2)) ||
        !(lambda(0) <= max_plane_variance)) {
      continue;
    }
    const Eigen::Vector3d normal = fit.eigenvectors.col(0);
    std::vector<std::uint32_t> near;
    for (const std::uint32_t k : same) {
      if (std::abs(normal.dot(world[k].cast<double>() - fit.mean)) <= gate_m) near.push_back(k);
    }
    if (near.empty()) continue;
    n.measured = Evenly(near, static_cast<std::size_t>(o.max_measured));
    chosen.push_back(std::move(n));
  }
  return chosen;
}

}  // namespace unimap::calibration
