#include "eval/LargestPlanes.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace unimap::eval {
namespace {

// A plane n . x = d with a unit normal.
struct Plane {
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  double d = 0.0;
  double Distance(const Eigen::Vector3f& p) const { return n.dot(p.cast<double>()) - d; }
};

// The least-squares plane through the points of indices (their centroid and
// the covariance's smallest eigenvector); false when fewer than 3.
bool FitPlane(const std::vector<Eigen::Vector3f>& points, const std::vector<std::size_t>& indices, Plane* plane) {
  if (indices.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i : indices) mean += points[i].cast<double>();
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i : indices) {
    const Eigen::Vector3d q = points[i].cast<double>() - mean;
    covariance += q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  plane->n = solver.eigenvectors().col(0).normalized();
  plane->d = plane->n.dot(mean);
  return true;
}

// The indices of the points of remaining within distance_m of the plane.
std::vector<std::size_t> Near(const std::vector<Eigen::Vector3f>& points, const std::vector<std::size_t>& remaining,
                              const Plane& plane, double distance_m) {
  std::vector<std::size_t> near;
  for (std::size_t i : remaining) {
    if (std::abs(plane.Distance(points[i])) <= distance_m) near.push_back(i);
  }
  return near;
}

double Median(std::vector<double> values) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// The RANSAC candidate with the most points of sample within inlier_distance_m.
bool BestCandidate(const std::vector<Eigen::Vector3f>& points, const std::vector<std::size_t>& sample,
                   const LargestPlanesOptions& options, std::mt19937_64* rng, Plane* best) {
  std::uniform_int_distribution<std::size_t> pick(0, sample.size() - 1);
  std::size_t best_count = 0;
  for (int it = 0; it < options.iterations; ++it) {
    const Eigen::Vector3d a = points[sample[pick(*rng)]].cast<double>();
    const Eigen::Vector3d b = points[sample[pick(*rng)]].cast<double>();
    const Eigen::Vector3d c = points[sample[pick(*rng)]].cast<double>();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-9) continue;  // collinear or repeated
    Plane candidate;
    candidate.n = normal.normalized();
    candidate.d = candidate.n.dot(a);
    // A plane through the sensor (near the map's origin) is seen edge-on: a
    // scan's own fan of rays, not a surface.
    if (std::abs(candidate.d) < options.min_offset_m) continue;
    std::size_t count = 0;
    for (std::size_t i : sample) count += std::abs(candidate.Distance(points[i])) <= options.inlier_distance_m ? 1 : 0;
    if (count > best_count) {
      best_count = count;
      *best = candidate;
    }
  }
  return best_count >= 3;
}

}  // namespace

bool LargestPlanesOptions::IsValid(std::string* why) const {
  std::string local;
  if (why == nullptr) why = &local;
  if (max_planes < 1 || iterations < 1 || max_scored_points < 3) {
    *why = "max_planes and iterations must be at least 1, max_scored_points at least 3";
    return false;
  }
  if (!(inlier_distance_m > 0.0) || !(band_m >= inlier_distance_m) || !std::isfinite(band_m)) {
    *why = "inlier_distance_m must be positive and band_m at least inlier_distance_m";
    return false;
  }
  if (!(min_offset_m >= 0.0) || !std::isfinite(min_offset_m)) {
    *why = "min_offset_m must be zero or positive";
    return false;
  }
  if (!(min_share > 0.0 && min_share <= 1.0)) {
    *why = "min_share must be in (0, 1]";
    return false;
  }
  return true;
}

std::vector<MapPlane> FindLargestPlanes(const std::vector<Eigen::Vector3f>& points_map,
                                        const LargestPlanesOptions& options) {
  if (std::string why; !options.IsValid(&why)) throw std::invalid_argument("largest planes options: " + why);
  std::vector<MapPlane> planes;
  std::vector<std::size_t> remaining(points_map.size());
  for (std::size_t i = 0; i < remaining.size(); ++i) remaining[i] = i;
  const std::size_t min_points = std::max<std::size_t>(
      3, static_cast<std::size_t>(std::ceil(options.min_share * static_cast<double>(points_map.size()))));
  std::mt19937_64 rng(options.seed);
  while (static_cast<int>(planes.size()) < options.max_planes && remaining.size() >= min_points) {
    const std::size_t stride =
        std::max<std::size_t>(1, (remaining.size() + options.max_scored_points - 1) / options.max_scored_points);
    std::vector<std::size_t> sample;
    for (std::size_t k = 0; k < remaining.size(); k += stride) sample.push_back(remaining[k]);
    Plane plane;
    if (!BestCandidate(points_map, sample, options, &rng, &plane)) break;
    // Refit to all its supporting points, twice (the second with the refitted plane's support).
    for (int pass = 0; pass < 2; ++pass) {
      if (!FitPlane(points_map, Near(points_map, remaining, plane, options.inlier_distance_m), &plane)) break;
    }
    const std::vector<std::size_t> band = Near(points_map, remaining, plane, options.band_m);
    if (band.size() < min_points) break;
    std::vector<double> distances, ranges;
    distances.reserve(band.size());
    ranges.reserve(band.size());
    for (std::size_t i : band) {
      distances.push_back(std::abs(plane.Distance(points_map[i])));
      ranges.push_back(points_map[i].cast<double>().norm());
    }
    MapPlane found;
    const double sign = plane.d < 0.0 ? -1.0 : 1.0;
    found.normal = sign * plane.n;
    found.offset_m = sign * plane.d;
    found.points = band.size();
    found.thickness_m = 1.4826 * Median(std::move(distances));
    found.median_range_m = Median(std::move(ranges));
    planes.push_back(found);
    // The plane's points leave the search (band is sorted as remaining is).
    std::vector<std::size_t> rest;
    rest.reserve(remaining.size() - band.size());
    std::set_difference(remaining.begin(), remaining.end(), band.begin(), band.end(), std::back_inserter(rest));
    remaining.swap(rest);
  }
  return planes;
}

}  // namespace unimap::eval
