#include "map/LookupBenchmark.hpp"

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

namespace unimap::map {

namespace {

// Random points in the field's box (a unit cube for an empty field).
std::vector<Eigen::Vector3f> QueryPoints(const DistanceField& field, std::size_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const Eigen::Vector3f low = field.origin();
  Eigen::Vector3f size = field.box_max() - field.origin();
  if (field.CellCount() == 0) size = Eigen::Vector3f::Ones();
  std::vector<Eigen::Vector3f> points(std::min<std::size_t>(count, 1u << 20));
  for (Eigen::Vector3f& p : points) {
    p = low + Eigen::Vector3f(unit(rng), unit(rng), unit(rng)).cwiseProduct(size);
  }
  return points;
}

template <class Lookup>
double TimeLookups(const std::vector<Eigen::Vector3f>& points, std::size_t lookups, Lookup lookup) {
  if (points.empty() || lookups == 0) return 0.0;
  volatile float sink = 0.0f;
  float sum = 0.0f;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0, j = 0; i < lookups; ++i) {
    sum += lookup(points[j]);
    if (++j == points.size()) j = 0;
  }
  const auto stop = std::chrono::steady_clock::now();
  sink = sum;
  static_cast<void>(sink);
  return std::chrono::duration<double, std::nano>(stop - start).count() / static_cast<double>(lookups);
}

}  // namespace

double MeasureLookupNs(const DistanceField& field, std::size_t lookups, std::uint32_t seed) {
  const std::vector<Eigen::Vector3f> points = QueryPoints(field, lookups, seed);
  return TimeLookups(points, lookups, [&](const Eigen::Vector3f& p) { return field.Distance(p); });
}

double MeasureTrilinearLookupNs(const DistanceField& field, std::size_t lookups, std::uint32_t seed) {
  const std::vector<Eigen::Vector3f> points = QueryPoints(field, lookups, seed);
  Eigen::Vector3f gradient;
  return TimeLookups(points, lookups,
                     [&](const Eigen::Vector3f& p) { return field.DistanceTrilinear(p, &gradient) + gradient.x(); });
}

}  // namespace unimap::map
