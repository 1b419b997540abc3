#include "pipeline/Reacquirer.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "estimation/So3.hpp"
#include "map/SurfaceDistanceLayer.hpp"

namespace unimap::pipeline {
namespace {

using V3 = Eigen::Vector3f;

// Points on a 12 x 8 x 3 m room with a pillar and a cabinet (no symmetry
// that would make two poses alike), every ~5 cm.
std::vector<V3> Room() {
  std::vector<V3> points;
  const auto face = [&](const V3& origin, const V3& u, const V3& v) {
    for (float a = 0.0f; a <= 1.0f; a += 0.05f / u.norm()) {
      for (float b = 0.0f; b <= 1.0f; b += 0.05f / v.norm()) points.push_back(origin + a * u + b * v);
    }
  };
  face(V3(-6, -4, 0), V3(12, 0, 0), V3(0, 8, 0));  // floor
  face(V3(-6, -4, 3), V3(12, 0, 0), V3(0, 8, 0));  // ceiling
  face(V3(-6, -4, 0), V3(12, 0, 0), V3(0, 0, 3));  // walls
  face(V3(-6, 4, 0), V3(12, 0, 0), V3(0, 0, 3));
  face(V3(-6, -4, 0), V3(0, 8, 0), V3(0, 0, 3));
  face(V3(6, -4, 0), V3(0, 8, 0), V3(0, 0, 3));
  face(V3(2, 1, 0), V3(0.4f, 0, 0), V3(0, 0, 3));  // pillar
  face(V3(2, 1, 0), V3(0, 0.4f, 0), V3(0, 0, 3));
  face(V3(-4, -4, 0), V3(1.5f, 0, 0), V3(0, 0, 1.2f));  // cabinet front
  face(V3(-4, -3.4f, 1.2f), V3(1.5f, 0, 0), V3(0, -0.6f, 0));
  return points;
}

// The room seen from a sensor at T_map_body: every 7th room point, in the body frame.
std::vector<V3> ScanFrom(const Eigen::Isometry3d& T_map_body) {
  std::vector<V3> scan;
  const std::vector<V3> room = Room();
  const Eigen::Isometry3f T_body_map = T_map_body.inverse().cast<float>();
  for (std::size_t i = 0; i < room.size(); i += 7) scan.push_back(T_body_map * room[i]);
  return StridedSubset(scan, 300);
}

std::shared_ptr<const map::DistanceField> RoomField() {
  map::DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.clamp_distance_m = 0.5;
  map::SurfaceDistanceLayer layer(options);
  layer.Insert(Room(), V3(0, 0, 1.5f));
  return layer.Export(V3::Zero(), 0.0, 1);
}

TEST(Reacquirer, FindsAScanAMetreAndFiveDegreesFromThePrediction) {
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  truth.translation() = Eigen::Vector3d(0.5, -0.8, 1.2);
  truth.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // The prediction: 0.9 m and 0.4 m off, 5 degrees of heading (a constant-velocity
  // start at ~9 m/s and 50 deg/s over one 0.1 s sweep).
  Eigen::Isometry3d predicted = truth;
  predicted.translation() += Eigen::Vector3d(-0.9, 0.4, 0.0);
  predicted.linear() = Eigen::AngleAxisd(0.3 - 0.087, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  matching::Matrix6d covariance = matching::Matrix6d::Zero();
  covariance.diagonal() << 1.0, 1.0, 1.0, 0.01, 0.01, 0.01;  // 1 m, 0.1 rad: a velocity not known yet
  Reacquirer reacquirer(ReacquireOptions{});
  const auto field = RoomField();
  const std::vector<V3> scan = ScanFrom(truth);
  const ReacquireResult found = reacquirer.Search(field, predicted, covariance, scan, 0.1, 0.5);
  ASSERT_TRUE(found.ok) << found.reason;
  // To the field's precision: the minima of an unsigned field interpolated
  // between voxel centres lie up to half a voxel (here 5 cm) off the surface;
  // the localiser's refinement (with its prior) takes it from there.
  const Eigen::Isometry3d estimate = estimation::ApplyPoseError(predicted, found.error);
  EXPECT_LT((estimate.translation() - truth.translation()).norm(), 0.05);
  EXPECT_LT(Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle(), 0.01);
  EXPECT_LT(found.inliers_predicted, 0.7);
  EXPECT_GT(found.inliers_found, 0.95);
}

TEST(Reacquirer, KeepsACorrectPrediction) {
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  truth.translation() = Eigen::Vector3d(-1.0, 2.0, 1.0);
  matching::Matrix6d covariance = matching::Matrix6d::Identity() * 1e-4;
  Reacquirer reacquirer(ReacquireOptions{});
  const ReacquireResult found = reacquirer.Search(RoomField(), truth, covariance, ScanFrom(truth), 0.1, 0.5);
  ASSERT_TRUE(found.ok) << found.reason;
  // Within the field's precision (see above).
  EXPECT_LT(found.error.head<3>().norm(), 0.05);
  EXPECT_LT(found.error.tail<3>().norm(), 0.01);
}

TEST(Reacquirer, StridedSubsetKeepsEveryKthPoint) {
  std::vector<V3> points;
  for (int i = 0; i < 10; ++i) points.emplace_back(static_cast<float>(i), 0.0f, 0.0f);
  const std::vector<V3> subset = StridedSubset(points, 4);
  ASSERT_EQ(subset.size(), 4u);
  EXPECT_EQ(subset[1].x(), 3.0f);
  EXPECT_EQ(StridedSubset(points, 20).size(), 10u);
}

TEST(Reacquirer, InvalidOptionsAreRejected) {
  ReacquireOptions options;
  options.coarse_factor = 0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("coarse_factor"), std::string::npos);
}

}  // namespace
}  // namespace unimap::pipeline
