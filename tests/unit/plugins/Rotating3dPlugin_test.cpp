// rotating_3d: a VLP-16 on a turning motor sees a planar wall where it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "PluginTestSupport.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

using plugin_test::kDeg;
using plugin_test::kPi;

constexpr double kSpinHz = 10.0;
constexpr double kBlockPeriodS = 55.296e-6;  // VLP-16 firing cycle
constexpr int kBlocks = 1800;                // 358 deg of one revolution
constexpr double kWallX = 3.0;               // the wall: body x = 3 m
constexpr double kMotorRate = kPi;           // 30 rpm (rad/s)
constexpr double kEncoderStartS = 9.95;
constexpr double kEncoderStartRad = 1.0;
// DeskewScan's blend between its knots (docs/design.md 1.1) for a return at
// range_m: a static body, the motor at kMotorRate, the LiDAR 0.11 m off the motor axis.
double BlendBoundM(double range_m) { return DeskewBlendBoundM(range_m, 0.11, 0.0, kMotorRate); }

// A static body looking at the wall while the motor turns.
struct WallScan {
  RawScan scan;                              // LiDAR frame, true point times
  std::vector<Eigen::Vector3d> true_body_m;  // where each return is, body frame
};

// Unwrapped encoder angle of the synthetic motor.
double EncoderAngle(double t) { return kEncoderStartRad + kMotorRate * (t - kEncoderStartS); }

// One clockwise VLP-16 sweep starting at t0; each ray is cast from the LiDAR
// pose at its firing time (motor angle from the encoder truth) to the wall.
WallScan MakeWallScan(const plugin_test::MountTruth& mount, double t0_s) {
  WallScan out;
  out.scan.start_time_s = t0_s;
  out.scan.end_time_s = t0_s + kBlockPeriodS * (kBlocks - 1);
  for (int k = 0; k < kBlocks; ++k) {
    const double t = t0_s + kBlockPeriodS * static_cast<double>(k);
    const double azimuth = -2.0 * kPi * kSpinHz * (t - t0_s);
    const Eigen::Isometry3d T_body_lidar = mount.BodyFromLidar(mount.MotorAngle(EncoderAngle(t)));
    for (int r = 0; r < 16; ++r) {
      const double elevation = (-15.0 + 2.0 * static_cast<double>(r)) * kDeg;
      const Eigen::Vector3d u(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                              std::sin(elevation));
      const Eigen::Vector3d d = T_body_lidar.linear() * u;
      if (d.x() < 1e-3) continue;
      const double s = (kWallX - T_body_lidar.translation().x()) / d.x();
      if (s < 0.5 || s > 90.0) continue;
      Point p;
      p.position_m = s * u;
      p.time_s = t;
      p.ring = static_cast<std::uint16_t>(r);
      out.scan.points.push_back(p);
      out.true_body_m.push_back(T_body_lidar.translation() + s * d);
    }
  }
  return out;
}

class Rotating3dPluginTest : public ::testing::Test {
 protected:
  void SetUp() override {
    loaded_ = plugin_test::LoadPayload("rotating_3d");
    plugin_test::ConfigureWith(loaded_.plugin.get(), mount_.Overrides());
    encoder_ = plugin_test::ConstantRateEncoder(kEncoderStartS, 10.3, kEncoderStartRad, kMotorRate, 100.0);
  }
  PayloadPlugin& plugin() { return *loaded_.plugin; }

  plugin_test::MountTruth mount_;
  LoadedPlugin loaded_;
  EncoderTrack encoder_;
};

TEST_F(Rotating3dPluginTest, WallPointsLandOnTheWallWithAStaticBody) {
  EXPECT_EQ(plugin().Name(), "rotating_3d");
  EXPECT_TRUE(plugin().UsesEncoder());
  const WallScan wall = MakeWallScan(mount_, 10.0);
  ASSERT_GT(wall.scan.points.size(), 5000u);
  const BodyScan out = plugin().Deskew(wall.scan, encoder_, plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), wall.scan.points.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_LT(std::abs(out.points[i].position_m.x() - kWallX), 1e-3) << "point " << i;
    ASSERT_LT((out.points[i].position_m - wall.true_body_m[i]).norm(),
              BlendBoundM(wall.scan.points[i].position_m.norm()))
        << "point " << i;
  }
  // One motor angle for the whole sweep (the scan end's) would miss the wall
  // by centimetres: the per-point encoder synchronisation is what the test sees.
  const Eigen::Isometry3d T_end = plugin().BodyFromLidarAt(encoder_, wall.scan.end_time_s);
  double worst_m = 0.0;
  for (const Point& p : wall.scan.points) {
    worst_m = std::max(worst_m, std::abs((T_end * p.position_m).x() - kWallX));
  }
  EXPECT_GT(worst_m, 0.05);
}

TEST_F(Rotating3dPluginTest, DerivesFiringTimesThenMotorAnglesForUnstampedSweeps) {
  WallScan wall = MakeWallScan(mount_, 10.0);
  ASSERT_FALSE(wall.scan.points.empty());
  // The first return must come from the first block for its azimuth to mark start_time_s.
  ASSERT_EQ(wall.scan.points.front().time_s, 10.0);
  std::vector<double> true_time_s;
  for (Point& p : wall.scan.points) {
    true_time_s.push_back(p.time_s);
    p.time_s = 0.0;
  }
  wall.scan.has_point_time = false;
  wall.scan.end_time_s = wall.scan.start_time_s;
  const BodyScan out = plugin().Deskew(wall.scan, encoder_, plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), wall.scan.points.size());
  EXPECT_NEAR(out.reference_time_s, *std::max_element(true_time_s.begin(), true_time_s.end()), 1e-9);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_NEAR(out.points[i].time_s, true_time_s[i], 1e-9) << "point " << i;
    ASSERT_LT((out.points[i].position_m - wall.true_body_m[i]).norm(),
              BlendBoundM(wall.scan.points[i].position_m.norm()))
        << "point " << i;
  }
}

}  // namespace
}  // namespace unimap
