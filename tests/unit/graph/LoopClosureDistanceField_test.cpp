#include "graph/LoopClosureDistanceField.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::graph {
namespace {

std::vector<Eigen::Vector3f> RandomPoints(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 2.0f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), 0.5f * u(rng));
  return points;
}

float NearestDistance(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& q) {
  float best = std::numeric_limits<float>::max();
  for (const auto& p : points) best = std::min(best, (p - q).norm());
  return best;
}

TEST(LoopClosureDistanceFieldTest, CellsHoldTheDistanceToTheNearestPointUpToTheClamp) {
  const auto points = RandomPoints(80, 1);
  const double resolution = 0.1;
  const double clamp = 0.3;
  const LoopClosureDistanceField field(points, resolution, clamp, 0.2, 0.1);
  const Eigen::Vector3f origin = field.origin();
  int near_cells = 0;
  for (int x = 0; x < 40; ++x) {
    for (int y = 0; y < 40; ++y) {
      for (int z = 0; z < 20; z += 3) {
        const Eigen::Vector3f center =
            origin + (Eigen::Vector3i(x, y, z).cast<float>() + Eigen::Vector3f::Constant(0.5f)) * 0.1f;
        const float truth = std::min(static_cast<float>(clamp), NearestDistance(points, center));
        ASSERT_NEAR(field.CellDistance(x, y, z), truth, clamp / 255.0 * 0.5 + 1e-5) << x << " " << y << " " << z;
        near_cells += truth < clamp ? 1 : 0;
        Eigen::Vector3f nearest;
        Eigen::Vector3f normal;
        const bool found = field.NearestPoint(center, &nearest, &normal);
        EXPECT_EQ(found, truth < clamp);
        if (found) {
          EXPECT_NEAR((nearest - center).norm(), truth, 1e-5);
        }
      }
    }
  }
  EXPECT_GT(near_cells, 1000);
}

TEST(LoopClosureDistanceFieldTest, TrilinearGradientMatchesFiniteDifferences) {
  // A plane z = 0 sampled every 5 cm: 0.15 m above it the field is smooth.
  std::vector<Eigen::Vector3f> plane;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) plane.emplace_back(0.05f * static_cast<float>(i), 0.05f * static_cast<float>(j), 0.0f);
  }
  const LoopClosureDistanceField field(plane, 0.1, 0.3, 0.2, 0.1);
  const Eigen::Vector3f p(1.03f, 0.97f, 0.153f);
  Eigen::Vector3f gradient;
  const float d = field.Distance(p, &gradient);
  EXPECT_NEAR(d, 0.153f, 0.01f);
  const float h = 1e-3f;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3f e = Eigen::Vector3f::Unit(a) * h;
    const float numeric = (field.Distance(p + e, nullptr) - field.Distance(p - e, nullptr)) / (2.0f * h);
    EXPECT_NEAR(gradient[a], numeric, 0.02f) << a;
  }
  EXPECT_NEAR(gradient.z(), 1.0f, 0.1f);
  Eigen::Vector3f nearest;
  Eigen::Vector3f normal;
  ASSERT_TRUE(field.NearestPoint(p, &nearest, &normal));
  EXPECT_NEAR(std::abs(normal.z()), 1.0f, 1e-4f);
}

TEST(LoopClosureDistanceFieldTest, FarPointsReadTheClampAndMemoryFollowsTheSurface) {
  // Two points 50 m apart: the box is large, the stored blocks are few.
  const std::vector<Eigen::Vector3f> points = {Eigen::Vector3f::Zero(), Eigen::Vector3f(50.0f, 50.0f, 5.0f)};
  const LoopClosureDistanceField field(points, 0.1, 0.3, 0.2, 0.1);
  Eigen::Vector3f gradient;
  EXPECT_FLOAT_EQ(field.Distance(Eigen::Vector3f(25.0f, 25.0f, 2.0f), &gradient), 0.3f);
  EXPECT_EQ(gradient, Eigen::Vector3f::Zero());
  EXPECT_FLOAT_EQ(field.Distance(Eigen::Vector3f(-100.0f, 0.0f, 0.0f), nullptr), 0.3f);
  EXPECT_FLOAT_EQ(field.Distance(Eigen::Vector3f(std::nanf(""), 0.0f, 0.0f), nullptr), 0.3f);
  Eigen::Vector3f nearest;
  Eigen::Vector3f normal;
  EXPECT_FALSE(field.NearestPoint(Eigen::Vector3f(25.0f, 25.0f, 2.0f), &nearest, &normal));
  EXPECT_LE(field.BlockCount(), 16u);
  EXPECT_LT(field.MemoryBytes(), 2'000'000u);  // a dense 8-bit grid would need ~12.5 MB
  EXPECT_NEAR(field.Distance(Eigen::Vector3f(0.0f, 0.0f, 0.2f), nullptr), 0.2f, 0.03f);
}

TEST(LoopClosureDistanceFieldTest, TooLargeABoxIsAnInputError) {
  const std::vector<Eigen::Vector3f> far = {Eigen::Vector3f::Zero(), Eigen::Vector3f(9000.0f, 9000.0f, 900.0f)};
  EXPECT_THROW(LoopClosureDistanceField(far, 0.1, 0.3, 0.2, 0.1), InputError);
}

}  // namespace
}  // namespace unimap::graph
