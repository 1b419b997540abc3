#include "map/WholeMapOptions.hpp"

#include <gtest/gtest.h>

#include "map/DistanceMap.hpp"

namespace unimap::map {
namespace {

// A floor 60 m long and 4 m wide at z = 0, sampled every 5 cm.
std::vector<Eigen::Vector3f> LongFloor() {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i <= 1200; ++i) {
    for (int j = -40; j <= 40; ++j) {
      points.emplace_back(0.05f * static_cast<float>(i), 0.05f * static_cast<float>(j), 0.0f);
    }
  }
  return points;
}

DistanceMapOptions Options() {
  DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.max_range_m = 10.0;
  options.clamp_distance_m = 0.5;
  options.subvoxel_surfaces = true;
  return options;
}

TEST(WholeMapOptions, OneFixedBoxReachesEveryPoint) {
  const Eigen::Vector3f center(2.0f, 0.0f, 1.0f);
  const std::optional<DistanceMapOptions> whole = WholeMapOptions(LongFloor(), Options(), center);
  ASSERT_TRUE(whole.has_value());
  EXPECT_FALSE(whole->follow_sensor);
  // From x = 2 the far end (60 m) and its padding (0.5 m clamp + one voxel) must be inside.
  EXPECT_GE(whole->max_range_m, 58.0 + 0.6);
  EXPECT_LT(whole->max_range_m, 58.0 + 0.8);
  EXPECT_DOUBLE_EQ(whole->resolution_m, 0.1);

  // Far beyond the original 10 m box, without moving the sensor: exact distances to the floor.
  const auto map = DistanceMap::FromPoints(LongFloor(), *whole, center);
  map->WaitForUpdates();
  const auto field = map->Snapshot();
  for (const float x : {1.0f, 30.0f, 55.0f, 59.5f}) {
    EXPECT_NEAR(field->DistanceTrilinear(Eigen::Vector3f(x, 0.3f, 0.2f), nullptr), 0.2f, 0.02f) << x;
    EXPECT_NEAR(field->DistanceTrilinear(Eigen::Vector3f(x, -0.7f, 0.05f), nullptr), 0.05f, 0.02f) << x;
  }
}

TEST(WholeMapOptions, RefusesMapsOverTheCellBudgetAndEmptyInput) {
  DistanceMapOptions small = Options();
  small.max_edt_cells = 100000;  // 60 m x 4 m x 1 m plus the clamp needs ~380k cells at 0.1 m
  EXPECT_FALSE(WholeMapOptions(LongFloor(), small, Eigen::Vector3f::Zero()).has_value());
  EXPECT_FALSE(WholeMapOptions({}, Options(), Eigen::Vector3f::Zero()).has_value());
  EXPECT_FALSE(WholeMapOptions(LongFloor(), Options(), Eigen::Vector3f::Constant(NAN)).has_value());
}

TEST(WholeMapOptions, RefusesABoxBeyondTheOctreeKeyRange) {
  // At 0.1 m the octree's keys reach +-3276.7 m; the centre plus the box's
  // reach (about 59 m here) must stay inside.
  std::vector<Eigen::Vector3f> far = LongFloor();
  for (Eigen::Vector3f& p : far) p.x() += 3150.0f;
  EXPECT_TRUE(WholeMapOptions(far, Options(), Eigen::Vector3f(3152.0f, 0.0f, 1.0f)).has_value());
  for (Eigen::Vector3f& p : far) p.x() += 100.0f;
  EXPECT_FALSE(WholeMapOptions(far, Options(), Eigen::Vector3f(3252.0f, 0.0f, 1.0f)).has_value());
}

}  // namespace
}  // namespace unimap::map
