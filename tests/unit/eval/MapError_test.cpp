#include "eval/MapError.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

// Exact distance to the infinite plane n . p = c (n unit length).
struct Plane {
  Eigen::Vector3d n;
  double c;
  double operator()(const Eigen::Vector3d& p) const { return std::abs(n.dot(p) - c); }
};

// A tilted plane through (0, 0, 2): n = normalised (1, 2, 3).
Plane Tilted() {
  const Eigen::Vector3d n = Eigen::Vector3d(1.0, 2.0, 3.0).normalized();
  return {n, n.dot(Eigen::Vector3d(0.0, 0.0, 2.0))};
}

// Points offset from the plane by offsets[i] (alternating sides), at random
// in-plane positions (fixed seed). Floats: the in-plane spread is kept small so
// the float rounding of the coordinates stays below 1e-6 m.
std::vector<Eigen::Vector3f> OffsetPoints(const Plane& plane, const std::vector<double>& offsets) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
  const Eigen::Vector3d u = plane.n.unitOrthogonal();
  const Eigen::Vector3d v = plane.n.cross(u);
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double side = i % 2 == 0 ? 1.0 : -1.0;
    const Eigen::Vector3d p =
        plane.c * plane.n + coordinate(rng) * u + coordinate(rng) * v + side * offsets[i] * plane.n;
    points.push_back(p.cast<float>());
  }
  return points;
}

TEST(MapError, OffsetsFromAPlaneGiveTheirMeanPercentileAndMax) {
  // d = 0.01 k for k = 1..100 in shuffled order: mean 0.505, nearest rank
  // ceil(0.95 * 100) = 95 -> 0.95, max 1.0.
  std::vector<double> offsets(100);
  std::iota(offsets.begin(), offsets.end(), 1.0);
  for (double& d : offsets) d *= 0.01;
  std::shuffle(offsets.begin(), offsets.end(), std::mt19937(3));
  const Plane plane = Tilted();
  const MapErrorStats stats = ComputeMapError(OffsetPoints(plane, offsets), plane);
  EXPECT_EQ(stats.points, 100u);
  EXPECT_NEAR(stats.mean_m, 0.505, 1e-6);
  EXPECT_NEAR(stats.p95_m, 0.95, 1e-6);
  EXPECT_NEAR(stats.max_m, 1.0, 1e-6);
}

TEST(MapError, PercentileIsTheNearestRank) {
  // The distance function reads the offset straight from x, so values are exact.
  const auto by_x = [](const Eigen::Vector3d& p) { return p.x(); };
  const auto points = [](std::size_t n) {
    std::vector<Eigen::Vector3f> out;
    for (std::size_t k = n; k >= 1; --k) out.emplace_back(static_cast<float>(k), 0.0f, 0.0f);  // descending
    return out;
  };
  // rank = ceil(0.95 n): n = 1 -> 1, 19 -> 19 (the max), 20 -> 19, 21 -> 20, 40 -> 38, 41 -> 39.
  const std::pair<std::size_t, double> cases[] = {{1, 1.0}, {19, 19.0}, {20, 19.0}, {21, 20.0}, {40, 38.0}, {41, 39.0}};
  for (const auto& [n, p95] : cases) {
    const MapErrorStats stats = ComputeMapError(points(n), by_x);
    EXPECT_EQ(stats.p95_m, p95) << "n = " << n;
    EXPECT_EQ(stats.max_m, static_cast<double>(n)) << "n = " << n;
    EXPECT_EQ(stats.mean_m, (static_cast<double>(n) + 1.0) / 2.0) << "n = " << n;
  }
}

TEST(MapError, PointsOnTheSurfaceHaveZeroError) {
  const Plane floor{Eigen::Vector3d::UnitZ(), 0.0};
  const MapErrorStats stats = ComputeMapError(OffsetPoints(floor, std::vector<double>(37, 0.0)), floor);
  EXPECT_EQ(stats.points, 37u);
  EXPECT_EQ(stats.mean_m, 0.0);
  EXPECT_EQ(stats.p95_m, 0.0);
  EXPECT_EQ(stats.max_m, 0.0);
}

TEST(MapError, TheDistanceFunctionSeesEveryPointInDouble) {
  std::vector<Eigen::Vector3d> seen;
  const std::vector<Eigen::Vector3f> points = {Eigen::Vector3f(0.1f, 0.2f, 0.3f), Eigen::Vector3f(-7.0f, 1e-3f, 5.0f)};
  ComputeMapError(points, [&](const Eigen::Vector3d& p) {
    seen.push_back(p);
    return 1.0;
  });
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0], points[0].cast<double>());
  EXPECT_EQ(seen[1], points[1].cast<double>());
}

// Expects an InputError whose message contains part.
template <typename F>
void ExpectError(const std::vector<Eigen::Vector3f>& points, F distance, const std::string& part) {
  try {
    ComputeMapError(points, distance);
    ADD_FAILURE() << "expected InputError containing '" << part << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(MapError, BadInputIsAnInputError) {
  const auto unit = [](const Eigen::Vector3d&) { return 1.0; };
  ExpectError({}, unit, "no points");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  ExpectError({Eigen::Vector3f::Zero(), Eigen::Vector3f(0.0f, nan, 0.0f)}, unit, "point 1 is not finite");
  const std::vector<Eigen::Vector3f> three(3, Eigen::Vector3f::Ones());
  int calls = 0;
  const auto infinite_third = [&](const Eigen::Vector3d&) {
    return ++calls == 3 ? std::numeric_limits<double>::infinity() : 0.5;
  };
  ExpectError(three, infinite_third, "point 2 has no finite distance");
  ExpectError(
      three, [](const Eigen::Vector3d&) { return -0.1; }, "point 0 has no finite distance");
  ExpectError(
      three, [](const Eigen::Vector3d&) { return std::nan(""); }, "point 0 has no finite distance");
}

}  // namespace
}  // namespace unimap::eval
