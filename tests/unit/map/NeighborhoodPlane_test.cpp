#include "map/NeighborhoodPlane.hpp"

#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

constexpr float kResolution = 0.1f;
constexpr float kClamp = 1.0f;
const Eigen::Vector3f kOrigin(-1.0f, -1.0f, -1.0f);
const Eigen::Vector3i kDims(20, 20, 20);

// A voxel-centre field over [-1, 1)^3 whose surface cells (distance 0) are
// those surface(centre) picks; every other cell reads one cell edge.
DistanceField FieldOf(const std::function<bool(const Eigen::Vector3f&)>& surface) {
  std::vector<std::uint16_t> cells;
  for (int x = 0; x < kDims.x(); ++x) {
    for (int y = 0; y < kDims.y(); ++y) {
      for (int z = 0; z < kDims.z(); ++z) {
        const Eigen::Vector3f center =
            kOrigin + (Eigen::Vector3i(x, y, z).cast<float>().array() + 0.5f).matrix() * kResolution;
        cells.push_back(DistanceField::Quantise(surface(center) ? 0.0f : kResolution, kClamp));
      }
    }
  }
  return DistanceField(kOrigin, kDims, kResolution, kClamp, std::move(cells), 1);
}

TEST(NeighborhoodPlane, RecoversATiltedPlaneFromItsVoxels) {
  const Eigen::Vector3f n = Eigen::Vector3f(0.3f, -0.2f, 1.0f).normalized();
  const float offset = 0.02f;  // n . x + offset = 0
  const DistanceField field =
      FieldOf([&](const Eigen::Vector3f& c) { return std::abs(n.dot(c) + offset) <= 0.5f * kResolution; });
  const Eigen::Vector3f p(0.07f, -0.04f, 0.0f);
  const NeighborhoodPlane plane = FitNeighborhoodPlane(field, p, NeighborhoodPlaneOptions{});
  ASSERT_EQ(plane.shape, NeighborhoodShape::kPlanar);
  EXPECT_NEAR(std::abs(plane.normal_map.dot(n)), 1.0f, 1e-3f);  // within 2.6 deg
  EXPECT_NEAR(plane.normal_map.norm(), 1.0f, 1e-5f);
  // A point on the true plane is on the fitted one to within a few mm.
  const Eigen::Vector3f on_plane = p - (n.dot(p) + offset) * n;
  EXPECT_LT(std::abs(plane.normal_map.dot(on_plane) + plane.offset_m), 0.005f);
}

TEST(NeighborhoodPlane, StripesOfAWallMakeItsPlaneOneStripeDoesNot) {
  // A line scanner's stripes on the wall y = 0.05: vertical lines of voxels
  // 0.3 m apart in x.
  const auto stripes = [](const Eigen::Vector3f& c) {
    const int column = static_cast<int>(std::lround((c.x() + 1.0f) / kResolution - 0.5f));
    return std::abs(c.y() - 0.05f) < 1e-3f && column % 3 == 0;
  };
  const DistanceField striped = FieldOf(stripes);
  // Between two stripes: the neighbourhood (radius 3 cells) holds three.
  const NeighborhoodPlane wall = FitNeighborhoodPlane(striped, Eigen::Vector3f(0.02f, 0.05f, 0.0f), {});
  ASSERT_EQ(wall.shape, NeighborhoodShape::kPlanar);
  EXPECT_NEAR(std::abs(wall.normal_map.y()), 1.0f, 1e-5f);
  EXPECT_NEAR(std::abs(wall.normal_map.y() * 0.05f + wall.offset_m), 0.0f, 1e-5f);
  // A radius of one cell sees a single stripe: a line, no plane.
  NeighborhoodPlaneOptions narrow;
  narrow.radius_cells = 1;
  narrow.min_cells = 3;  // the stripe's three cells in reach
  const Eigen::Vector3f on_stripe(-0.95f + 0.3f, 0.05f, 0.0f);
  EXPECT_EQ(FitNeighborhoodPlane(striped, on_stripe, narrow).shape, NeighborhoodShape::kLinear);
}

TEST(NeighborhoodPlane, ACornerIsNotAPlane) {
  const DistanceField corner = FieldOf(
      [](const Eigen::Vector3f& c) { return std::abs(c.x() - 0.05f) < 1e-3f || std::abs(c.y() - 0.05f) < 1e-3f; });
  EXPECT_EQ(FitNeighborhoodPlane(corner, Eigen::Vector3f(0.05f, 0.05f, 0.0f), {}).shape,
            NeighborhoodShape::kVolumetric);
}

TEST(NeighborhoodPlane, TooFewSurfaceCellsOrNoFieldGiveNoPlane) {
  // Three cells in a row: fewer than min_cells (6).
  const DistanceField sparse = FieldOf([](const Eigen::Vector3f& c) {
    return std::abs(c.y() - 0.05f) < 1e-3f && std::abs(c.z() - 0.05f) < 1e-3f && std::abs(c.x() - 0.05f) < 0.11f;
  });
  EXPECT_EQ(FitNeighborhoodPlane(sparse, Eigen::Vector3f(0.05f, 0.05f, 0.05f), {}).shape, NeighborhoodShape::kTooFew);
  EXPECT_EQ(FitNeighborhoodPlane(DistanceField(kClamp), Eigen::Vector3f::Zero(), {}).shape, NeighborhoodShape::kTooFew);
  const DistanceField floor = FieldOf([](const Eigen::Vector3f& c) { return std::abs(c.z() - 0.05f) < 1e-3f; });
  EXPECT_EQ(FitNeighborhoodPlane(floor, Eigen::Vector3f(NAN, 0.0f, 0.0f), {}).shape, NeighborhoodShape::kTooFew);
  // Far outside the grid: nothing around.
  EXPECT_EQ(FitNeighborhoodPlane(floor, Eigen::Vector3f(50.0f, 0.0f, 0.0f), {}).shape, NeighborhoodShape::kTooFew);
}

TEST(NeighborhoodPlaneOptions, RejectsOutOfRangeSettings) {
  std::string why;
  EXPECT_TRUE(NeighborhoodPlaneOptions{}.IsValid(&why)) << why;
  NeighborhoodPlaneOptions o;
  o.radius_cells = 0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("radius_cells"), std::string::npos);
  o = {};
  o.min_cells = 2;
  EXPECT_FALSE(o.IsValid(&why));
  o = {};
  o.max_thickness_ratio = 1.0;
  EXPECT_FALSE(o.IsValid(&why));
  o = {};
  o.min_spread_ratio = 0.0;
  EXPECT_FALSE(o.IsValid(&why));
}

}  // namespace
}  // namespace unimap::map
