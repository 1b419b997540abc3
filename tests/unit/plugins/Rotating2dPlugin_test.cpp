// rotating_2d: a Hokuyo on a turning motor sees a planar wall where it is,
// every beam with the motor angle at its own firing time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "PluginTestSupport.hpp"
#include "unimap/Errors.hpp"
#include "unimap/LineScan.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

using plugin_test::kDeg;
using plugin_test::kPi;

constexpr int kBeams = 1081;                              // UTM-30LX: 270 deg in 0.25 deg steps
constexpr double kLinePeriodS = 1.0 / 40.0;               // 40 Hz
constexpr double kBeamIntervalS = 0.25 / (360.0 * 40.0);  // mirror turns 0.25 deg
constexpr double kWallX = 2.5;                            // the wall: body x = 2.5 m
constexpr double kMotorRate = kPi;                        // 30 rpm (rad/s)
constexpr double kEncoderStartS = 9.9;
constexpr double kEncoderStartRad = 4.0;
// DeskewScan's blend between its knots (docs/design.md 1.1) for a return at
// range_m: a static body, the motor at kMotorRate, the LiDAR 0.11 m off the motor axis.
double BlendBoundM(double range_m) { return DeskewBlendBoundM(range_m, 0.11, 0.0, kMotorRate); }

// Unwrapped encoder angle of the synthetic motor.
double EncoderAngle(double t) { return kEncoderStartRad + kMotorRate * (t - kEncoderStartS); }

// One line as the scanner reports it, with where its kept returns truly are.
struct WallLine {
  LineScan line;
  std::vector<Eigen::Vector3d> true_body_m;  // one per kept beam, in beam order
};

// Casts every beam from the scanner pose at its firing time to the wall.
WallLine MakeWallLine(const plugin_test::MountTruth& mount, double t0_s) {
  WallLine out;
  out.line.start_time_s = t0_s;
  out.line.angle_min_rad = -135.0 * kDeg;
  out.line.angle_increment_rad = 0.25 * kDeg;
  out.line.time_increment_s = kBeamIntervalS;
  out.line.range_min_m = 0.1;
  out.line.range_max_m = 30.0;
  for (int i = 0; i < kBeams; ++i) {
    const double t = t0_s + kBeamIntervalS * static_cast<double>(i);
    const double angle = out.line.angle_min_rad + out.line.angle_increment_rad * i;
    const Eigen::Isometry3d T_body_lidar = mount.BodyFromLidar(mount.MotorAngle(EncoderAngle(t)));
    const Eigen::Vector3d u(std::cos(angle), std::sin(angle), 0.0);
    const Eigen::Vector3d d = T_body_lidar.linear() * u;
    float range = std::numeric_limits<float>::quiet_NaN();
    if (d.x() > 1e-3) range = static_cast<float>((kWallX - T_body_lidar.translation().x()) / d.x());
    out.line.ranges_m.push_back(range);
    if (std::isfinite(range) && range >= 0.1f && range <= 30.0f) {
      out.true_body_m.push_back(T_body_lidar.translation() + static_cast<double>(range) * d);
    }
  }
  return out;
}

class Rotating2dPluginTest : public ::testing::Test {
 protected:
  void SetUp() override {
    loaded_ = plugin_test::LoadPayload("rotating_2d");
    plugin_test::ConfigureWith(loaded_.plugin.get(), mount_.Overrides());
    encoder_ = plugin_test::ConstantRateEncoder(kEncoderStartS, 11.0, kEncoderStartRad, kMotorRate, 50.0);
  }
  PayloadPlugin& plugin() { return *loaded_.plugin; }

  plugin_test::MountTruth mount_;
  LoadedPlugin loaded_;
  EncoderTrack encoder_;
};

TEST_F(Rotating2dPluginTest, WallPointsLandOnTheWallWithAStaticBody) {
  EXPECT_EQ(plugin().Name(), "rotating_2d");
  EXPECT_TRUE(plugin().UsesEncoder());
  std::size_t total = 0;
  double worst_single_angle_m = 0.0;
  // 20 lines: half a second, a quarter motor revolution.
  for (int j = 0; j < 20; ++j) {
    const WallLine wall = MakeWallLine(mount_, 10.0 + kLinePeriodS * j);
    const LineScanConversion converted = LineScanToRawScan(wall.line);
    if (converted.scan.points.empty()) continue;
    const BodyScan out = plugin().Deskew(converted.scan, encoder_, plugin_test::StaticBody());
    ASSERT_EQ(out.points.size(), wall.true_body_m.size()) << "line " << j;
    for (std::size_t i = 0; i < out.points.size(); ++i) {
      ASSERT_LT(std::abs(out.points[i].position_m.x() - kWallX), 1e-3) << "line " << j << " " << i;
      ASSERT_LT((out.points[i].position_m - wall.true_body_m[i]).norm(),
                BlendBoundM(converted.scan.points[i].position_m.norm()))
          << j << " " << i;
    }
    total += out.points.size();
    // The same line with one motor angle (its end's) for every beam.
    const Eigen::Isometry3d T_end = plugin().BodyFromLidarAt(encoder_, converted.scan.end_time_s);
    for (const Point& p : converted.scan.points) {
      worst_single_angle_m = std::max(worst_single_angle_m, std::abs((T_end * p.position_m).x() - kWallX));
    }
  }
  EXPECT_GT(total, 5000u);
  // Per-beam motor angles matter: 4.5 deg of motor turn within one line.
  EXPECT_GT(worst_single_angle_m, 0.05);
}

TEST_F(Rotating2dPluginTest, DerivesBeamTimesFromAzimuthForUnstampedLines) {
  // The first line (from 10 s, every 25 ms) with plenty of wall returns.
  WallLine wall;
  for (int j = 0; j < 40 && wall.true_body_m.size() < 300; ++j) {
    wall = MakeWallLine(mount_, 10.0 + kLinePeriodS * j);
  }
  ASSERT_GE(wall.true_body_m.size(), 300u);
  const double start_s = wall.line.start_time_s;
  // Drop the first returns: beam times must not depend on which point comes first.
  int dropped_first = 0;
  for (int i = 0; i < kBeams && dropped_first < 10; ++i) {
    if (std::isfinite(wall.line.ranges_m[i])) {
      wall.line.ranges_m[i] = std::numeric_limits<float>::quiet_NaN();
      wall.true_body_m.erase(wall.true_body_m.begin());
      ++dropped_first;
    }
  }
  const LineScanConversion stamped = LineScanToRawScan(wall.line);
  ASSERT_GT(stamped.scan.points.size(), 200u);
  RawScan unstamped = stamped.scan;
  for (Point& p : unstamped.points) p.time_s = 0.0;
  unstamped.has_point_time = false;
  unstamped.end_time_s = unstamped.start_time_s;

  const BodyScan out = plugin().Deskew(unstamped, encoder_, plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), stamped.scan.points.size());
  EXPECT_NEAR(out.reference_time_s, start_s + kBeamIntervalS * (kBeams - 1), 1e-12);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_NEAR(out.points[i].time_s, stamped.scan.points[i].time_s, 1e-12) << "point " << i;
    ASSERT_LT((out.points[i].position_m - wall.true_body_m[i]).norm(),
              BlendBoundM(stamped.scan.points[i].position_m.norm()))
        << "point " << i;
  }
}

TEST_F(Rotating2dPluginTest, UnstampedPointOutsideTheFieldOfViewIsAnInputError) {
  RawScan scan;
  scan.start_time_s = 10.0;
  scan.end_time_s = 10.0;
  scan.has_point_time = false;
  Point ahead;
  ahead.position_m = Eigen::Vector3d(2.0, 0.0, 0.0);
  Point behind;  // azimuth 180 deg: in the UTM-30LX's 90 deg blind sector
  behind.position_m = Eigen::Vector3d(-2.0, 0.01, 0.0);
  scan.points = {ahead, behind};
  try {
    plugin().Deskew(scan, encoder_, plugin_test::StaticBody());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unimap
