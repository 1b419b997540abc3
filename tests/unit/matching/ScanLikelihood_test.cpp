#include "matching/ScanLikelihood.hpp"

#include <gtest/gtest.h>

#include "AnalyticFields.hpp"

namespace unimap::matching {
namespace {

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

}  // namespace
}  // namespace unimap::matching
