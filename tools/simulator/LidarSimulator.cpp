#include "LidarSimulator.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace unimap::sim {

LidarSimulator::LidarSimulator(const World& world, LidarPoseTrack poses, LidarNoise noise, std::uint64_t seed)
    : world_(world), poses_(std::move(poses)), noise_(noise), rng_(seed) {
  if (!(std::isfinite(noise_.range_sigma_m) && noise_.range_sigma_m >= 0.0)) {
    throw std::invalid_argument("range noise sigma must be >= 0");
  }
  if (!(noise_.dropout_probability >= 0.0 && noise_.dropout_probability < 1.0)) {
    throw std::invalid_argument("dropout probability must be in [0, 1)");
  }
}

double LidarSimulator::Fire(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir_world, double min_range_m,
                            double max_range_m, float* intensity) {
  constexpr double kNoReturn = std::numeric_limits<double>::quiet_NaN();
  ++rays_;
  *intensity = 0.0f;
  // The dropout is drawn first so a dropped beam costs no ray cast.
  if (noise_.dropout_probability > 0.0 && uniform_(rng_) < noise_.dropout_probability) return kNoReturn;
  // Nearest surface in (0, max]: a surface closer than min_range hides what is behind it.
  const std::optional<RayHit> hit = world_.Cast(Ray{origin, dir_world}, 0.0, max_range_m);
  if (!hit || hit->range_m < min_range_m) return kNoReturn;
  double range = hit->range_m;
  if (noise_.range_sigma_m > 0.0) range += noise_.range_sigma_m * normal_(rng_);
  if (range < min_range_m || range > max_range_m) return kNoReturn;
  ++returns_;
  *intensity = static_cast<float>(100.0 * std::abs(hit->normal.dot(dir_world)));
  return range;
}

}  // namespace unimap::sim
