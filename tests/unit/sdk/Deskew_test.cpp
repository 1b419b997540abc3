#include "unimap/Deskew.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

// Constant linear and angular velocity: T_world_body(t) = (exp(w t), v t).
Eigen::Isometry3d BodyPose(double t) {
  const Eigen::Vector3d w(0.1, -0.2, 0.5);
  const Eigen::Vector3d v(1.0, 0.3, -0.1);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix();
  T.translation() = v * t;
  return T;
}

Eigen::Isometry3d Mount(double t) {  // a LiDAR spinning about body z at 2 rad/s, offset 0.1 m
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(2.0 * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.1, 0, 0);
  return T;
}

// Exact at the knots; between them within DeskewBlendBoundM (body 0.55
// rad/s and 1 m/s, mount 2 rad/s with a 0.1 m lever arm, 10 m ranges:
// 0.4 um).
TEST(DeskewScan, IsExactOnSyntheticMotionWithinTheKnotBound) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RawScan scan;
  scan.start_time_s = 5.0;
  scan.end_time_s = 5.1;
  std::vector<Eigen::Vector3d> world;
  for (int i = 0; i < 500; ++i) {
    const double t = 5.0 + 0.1 * i / 499.0;
    const Eigen::Vector3d p_world =
        BodyPose(t).translation() + 10.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    world.push_back(p_world);
    Point p;
    p.time_s = t;
    p.position_m = (BodyPose(t) * Mount(t)).inverse() * p_world;
    scan.points.push_back(p);
  }
  const BodyScan out = DeskewScan(scan, Mount, BodyPose, RangeLimits{});
  ASSERT_EQ(out.points.size(), world.size());
  EXPECT_EQ(out.reference_time_s, 5.1);
  const Eigen::Isometry3d T_body_world = BodyPose(5.1).inverse();
  const double h = kDeskewKnotSpacingS;
  const double bound_m = DeskewBlendBoundM(10.0, 0.1, Eigen::Vector3d(0.1, -0.2, 0.5).norm(), 2.0);
  for (std::size_t i = 0; i < world.size(); ++i) {
    const double error = (out.points[i].position_m - T_body_world * world[i]).norm();
    const double knots = (scan.points[i].time_s - scan.start_time_s) / h;
    if (std::abs(knots - std::round(knots)) < 1e-9 || scan.points[i].time_s == scan.end_time_s) {
      EXPECT_LT(error, 1e-9) << i;  // on a knot
    }
    EXPECT_LT(error, bound_m) << i;
  }
}

TEST(DeskewScan, DropsAndCountsOutOfRange) {
  RawScan scan;
  scan.end_time_s = 0.1;
  for (double r : {0.05, 1.0, 50.0, 20.0}) {
    Point p;
    p.position_m = Eigen::Vector3d(r, 0, 0);
    scan.points.push_back(p);
  }
  const auto identity = [](double) { return Eigen::Isometry3d::Identity(); };
  const BodyScan out = DeskewScan(scan, identity, identity, RangeLimits{0.1, 30.0});
  EXPECT_EQ(out.points.size(), 2u);
  EXPECT_EQ(out.dropped_out_of_range, 2u);
}

TEST(ValidateRawScan, RejectsBadInputNamingThePoint) {
  RawScan scan;
  scan.start_time_s = 1.0;
  scan.end_time_s = 2.0;
  EXPECT_THROW(ValidateRawScan(scan), InputError);  // empty
  Point good;
  good.time_s = 1.5;
  good.position_m = Eigen::Vector3d(1, 2, 3);
  scan.points = {good, good};
  EXPECT_NO_THROW(ValidateRawScan(scan));
  scan.points[1].position_m.y() = std::numeric_limits<double>::infinity();
  try {
    ValidateRawScan(scan);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
  }
  scan.points[1] = good;
  scan.points[1].time_s = 2.5;
  EXPECT_THROW(ValidateRawScan(scan), InputError);
  scan.points[1] = good;
  scan.end_time_s = 0.5;
  EXPECT_THROW(ValidateRawScan(scan), InputError);  // time going backwards
}

}  // namespace
}  // namespace unimap
