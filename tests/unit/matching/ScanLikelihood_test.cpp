#include "matching/ScanLikelihood.hpp"

#include <gtest/gtest.h>

#include "AnalyticFields.hpp"

namespace unimap::matching {
namespace {

// Three points tied to the plane x = 2 (normal +x, offset -2).
std::vector<PlanePoint> WallAtX2() {
  std::vector<PlanePoint> wall;
  for (int i = 0; i < 3; ++i) {
    wall.push_back({Eigen::Vector3f(2.0f, 0.3f * static_cast<float>(i), 1.0f), Eigen::Vector3f::UnitX(), -2.0f});
  }
  return wall;
}

TEST(ScanLikelihood, MatchesClosedFormOnKnownGeometry) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  // Points on the floor (z = -2) away from the other walls.
  std::vector<Eigen::Vector3f> floor;
  for (int i = 0; i < 20; ++i) floor.emplace_back(-2.0f + 0.2f * static_cast<float>(i), 0.5f, -2.0f);
  const ScanLikelihood likelihood(0.1, 0.5, 50.0);
  std::vector<Eigen::Vector3f> sp;
  std::vector<float> sd;
  EXPECT_NEAR(likelihood.LogLikelihood(room, Eigen::Isometry3d::Identity(), floor, &sp, &sd), 0.0, 1e-9);
  Eigen::Isometry3d up = Eigen::Isometry3d::Identity();
  up.translation().z() = 0.05;  // every point 5 cm from the floor
  EXPECT_NEAR(likelihood.LogLikelihood(room, up, floor, &sp, &sd), -50.0 * 0.05 * 0.05 / (2 * 0.01), 1e-4);
  up.translation().z() = 1.0;  // 1 m away: clamped at 0.5 m
  EXPECT_NEAR(likelihood.LogLikelihood(room, up, floor, &sp, &sd), -50.0 * 0.25 / 0.02, 1e-3);
}

TEST(ScanLikelihood, PlanePointsMeasureToTheirPlane) {
  // Field points on the floor plus points tied to the plane x = 2 (normal
  // +x, offset -2); n counts both.
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const std::vector<Eigen::Vector3f> floor = {{0.0f, 0.5f, -2.0f}, {1.0f, -0.5f, -2.0f}};
  const std::vector<PlanePoint> wall = WallAtX2();
  const ScanLikelihood likelihood(0.1, 0.5, 50.0);
  std::vector<Eigen::Vector3f> sp;
  std::vector<float> sd;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  EXPECT_NEAR(likelihood.LogLikelihood(room, T, floor, wall, &sp, &sd), 0.0, 1e-9);
  // 4 cm along x: the plane points are 4 cm off, the floor points are not;
  // 3 m along y moves nothing off the plane (no edge to pull towards).
  T.translation() = Eigen::Vector3d(0.04, 3.0, 0.0);
  EXPECT_NEAR(likelihood.LogLikelihood(room, T, {}, wall, &sp, &sd), -50.0 * 0.04 * 0.04 / (2 * 0.01), 1e-4);
  T.translation() = Eigen::Vector3d(0.04, 0.0, 0.0);
  EXPECT_NEAR(likelihood.LogLikelihood(room, T, floor, wall, &sp, &sd), -50.0 / 5.0 * 3.0 * 0.04 * 0.04 / (2 * 0.01),
              1e-4);
  T.translation() = Eigen::Vector3d(-1.0, 0.0, 0.0);  // 1 m off the plane: clamped at 0.5 m
  EXPECT_NEAR(likelihood.LogLikelihood(room, T, {}, wall, &sp, &sd), -50.0 * 0.25 / 0.02, 1e-3);
}

TEST(ScanLikelihood, UnmeasuredPointsCountInTheScanWithoutAMeasurement) {
  // Three plane points 4 cm off their plane and two points without a
  // measurement: n = 5, so the scan weighs 3/5 of what three measured
  // points alone would, whatever the pose does to the other two.
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const std::vector<PlanePoint> wall = WallAtX2();
  const ScanLikelihood likelihood(0.1, 0.5, 50.0);
  std::vector<Eigen::Vector3f> sp;
  std::vector<float> sd;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.04, 0.0, 0.0);
  const double alone = likelihood.LogLikelihood(room, T, {}, wall, &sp, &sd);
  EXPECT_NEAR(alone, -50.0 * 0.04 * 0.04 / (2 * 0.01), 1e-4);
  EXPECT_NEAR(likelihood.LogLikelihood(room, T, {}, wall, &sp, &sd, 2), alone * 3.0 / 5.0, 1e-4);
  // Nothing measured: no information, whatever is counted.
  EXPECT_EQ(likelihood.LogLikelihood(room, T, {}, {}, &sp, &sd, 7), 0.0);
}

}  // namespace
}  // namespace unimap::matching
