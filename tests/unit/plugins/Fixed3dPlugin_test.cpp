// fixed_3d: VLP-16 firing times derived from azimuth, fixed extrinsic.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "PluginTestSupport.hpp"
#include "unimap/Errors.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

using plugin_test::kDeg;
using plugin_test::kPi;

constexpr double kSpinHz = 10.0;
constexpr double kBlockPeriodS = 55.296e-6;  // VLP-16 firing cycle: 16 rings per block
constexpr int kBlocks = 1800;                // 358 deg of one 10 Hz revolution
constexpr int kRings = 16;

// One synthetic VLP-16 sweep in the LiDAR frame with the true firing times.
struct Sweep {
  RawScan scan;                     // point times zeroed, has_point_time = false
  std::vector<double> true_time_s;  // per point
};

// Block k fires at t0 + k * kBlockPeriodS with azimuth az0 -+ 2 pi f (t - t0)
// (clockwise: decreasing azimuth); ring r at elevation -15 + 2 r deg.
Sweep MakeSweep(double t0_s, double az0_rad, bool clockwise) {
  Sweep sweep;
  sweep.scan.start_time_s = t0_s;
  sweep.scan.end_time_s = t0_s;  // unknown: the plugin derives it
  sweep.scan.has_point_time = false;
  const double sign = clockwise ? -1.0 : 1.0;
  for (int k = 0; k < kBlocks; ++k) {
    const double t = t0_s + kBlockPeriodS * static_cast<double>(k);
    const double azimuth = az0_rad + sign * 2.0 * kPi * kSpinHz * (t - t0_s);
    for (int r = 0; r < kRings; ++r) {
      const double elevation = (-15.0 + 2.0 * static_cast<double>(r)) * kDeg;
      const double range = 4.0 + 0.3 * static_cast<double>(r) + 2.0 * std::sin(3.0 * azimuth);
      Point p;
      p.position_m = range * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                             std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      p.ring = static_cast<std::uint16_t>(r);
      sweep.scan.points.push_back(p);
      sweep.true_time_s.push_back(t);
    }
  }
  return sweep;
}

class Fixed3dPluginTest : public ::testing::Test {
 protected:
  void SetUp() override { loaded_ = plugin_test::LoadPayload("fixed_3d"); }
  PayloadPlugin& plugin() { return *loaded_.plugin; }

  LoadedPlugin loaded_;
};

TEST_F(Fixed3dPluginTest, IsAFixedMountWithoutEncoder) {
  EXPECT_EQ(plugin().Name(), "fixed_3d");
  EXPECT_FALSE(plugin().UsesEncoder());
  plugin_test::ConfigureWith(&plugin(), {{"extrinsic.body_lidar.translation_m", std::vector<double>{0.1, -0.2, 0.3}},
                                         {"extrinsic.body_lidar.rpy_deg", std::vector<double>{5.0, 10.0, -30.0}}});
  const EncoderTrack no_encoder;
  EXPECT_EQ(plugin().MotorAngleAt(no_encoder, 12.5), 0.0);
  const Eigen::Isometry3d expected = plugin_test::PoseRpyDeg(Eigen::Vector3d(0.1, -0.2, 0.3), 5.0, 10.0, -30.0);
  for (const double t : {0.0, 3.0, 1e6}) {
    EXPECT_TRUE(plugin().BodyFromLidarAt(no_encoder, t).isApprox(expected, 1e-12)) << t;
  }
}

TEST_F(Fixed3dPluginTest, DerivesClockwiseFiringTimesFromAzimuth) {
  plugin_test::ConfigureWith(&plugin(), {{"extrinsic.body_lidar.translation_m", std::vector<double>{0.0, 0.0, 0.0}}});
  // Start at 200 deg so the sweep crosses the -pi/pi azimuth seam.
  const Sweep sweep = MakeSweep(100.0, 200.0 * kDeg, /*clockwise=*/true);
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  EXPECT_EQ(out.dropped_out_of_range, 0u);
  EXPECT_NEAR(out.reference_time_s, sweep.true_time_s.back(), 1e-9);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_NEAR(out.points[i].time_s, sweep.true_time_s[i], 1e-9) << "point " << i;
    ASSERT_LT((out.points[i].position_m - sweep.scan.points[i].position_m).norm(), 1e-12) << i;
  }
}

TEST_F(Fixed3dPluginTest, Float32CoordinatesKeepEveryRingInItsFiring) {
  // Readers of PCD / KITTI files deliver float32 coordinates: the rings of one
  // block then differ in azimuth by ~1e-7 rad, which must not read as a whole
  // revolution (0.1 s) later.
  Sweep sweep = MakeSweep(50.0, 77.0 * kDeg, /*clockwise=*/true);
  for (Point& p : sweep.scan.points) p.position_m = p.position_m.cast<float>().cast<double>();
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  EXPECT_NEAR(out.reference_time_s, sweep.true_time_s.back(), 1e-8);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    // float32 azimuth error / (2 pi 10 Hz): well under 1e-8 s.
    ASSERT_NEAR(out.points[i].time_s, sweep.true_time_s[i], 1e-8) << "point " << i;
  }
}

TEST_F(Fixed3dPluginTest, DerivesCounterClockwiseFiringTimesWhenConfigured) {
  plugin_test::ConfigureWith(&plugin(), {{"lidar.clockwise", false}, {"lidar.spin_rate_hz", 10.0}});
  const Sweep sweep = MakeSweep(5.0, -10.0 * kDeg, /*clockwise=*/false);
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_NEAR(out.points[i].time_s, sweep.true_time_s[i], 1e-9) << "point " << i;
  }
}

TEST_F(Fixed3dPluginTest, DerivedTimesDeskewAMovingBodyExactly) {
  plugin_test::ConfigureWith(&plugin(), {{"extrinsic.body_lidar.translation_m", std::vector<double>{0.1, 0.0, 0.2}},
                                         {"extrinsic.body_lidar.rpy_deg", std::vector<double>{0.0, 10.0, 0.0}}});
  const Eigen::Isometry3d T_body_lidar = plugin_test::PoseRpyDeg(Eigen::Vector3d(0.1, 0.0, 0.2), 0.0, 10.0, 0.0);
  // 2 m/s forward while yawing at 1 rad/s: 0.2 m and 5.7 deg within one sweep.
  const MotionQuery T_world_body_at = [](double t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(1.0 * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(2.0 * t, 0.5, 0.0);
    return T;
  };
  const Sweep sweep = MakeSweep(1.0, 30.0 * kDeg, /*clockwise=*/true);
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), T_world_body_at);
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  const Eigen::Isometry3d T_body_world_ref = T_world_body_at(sweep.true_time_s.back()).inverse();
  double largest_motion_m = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    // p_body(t_ref) = T_world_body(t_ref)^-1 * T_world_body(t_i) * T_body_lidar * p_lidar
    const Eigen::Vector3d p_lidar = sweep.scan.points[i].position_m;
    const Eigen::Vector3d expected = T_body_world_ref * T_world_body_at(sweep.true_time_s[i]) * T_body_lidar * p_lidar;
    // DeskewScan's blend between its knots (docs/design.md 1.1): 1 rad/s, the
    // LiDAR 0.23 m off the body's axis.
    ASSERT_LT((out.points[i].position_m - expected).norm(), DeskewBlendBoundM(p_lidar.norm(), 0.23, 1.0, 0.0))
        << "point " << i;
    largest_motion_m = std::max(largest_motion_m, (expected - T_body_lidar * p_lidar).norm());
  }
  // The motion is large enough that wrong firing times would show.
  EXPECT_GT(largest_motion_m, 0.2);
}

TEST_F(Fixed3dPluginTest, KeepsPointTimesTheScanAlreadyHas) {
  Sweep sweep = MakeSweep(2.0, 0.0, /*clockwise=*/true);
  // Times that disagree with the azimuth (as if the head turned the other
  // way): a stamped scan is trusted, not re-derived.
  const double end_s = sweep.true_time_s.back();
  for (std::size_t i = 0; i < sweep.scan.points.size(); ++i) {
    sweep.scan.points[i].time_s = end_s - (sweep.true_time_s[i] - 2.0);
  }
  sweep.scan.end_time_s = end_s;
  sweep.scan.has_point_time = true;
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_EQ(out.points[i].time_s, sweep.scan.points[i].time_s) << i;
  }
  EXPECT_EQ(out.reference_time_s, end_s);
}

TEST_F(Fixed3dPluginTest, TimingNoneTakesAnUnstampedSweepAsASnapshotAtItsStart) {
  // A sweep already deskewed (KITTI) or from a sensor that does not spin:
  // no firing time is invented from the azimuth; every point is taken at the
  // sweep's start time, which is also the reference time.
  plugin_test::ConfigureWith(&plugin(), {{"lidar.timing", std::string("none")}});
  Sweep sweep = MakeSweep(7.0, 30.0 * kDeg, /*clockwise=*/true);
  sweep.scan.end_time_s = 7.1;  // the frame period a reader may give
  const MotionQuery moving = [](double t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(10.0 * t, 0.0, 0.0);  // 10 m/s: 1 m per 0.1 s
    return T;
  };
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), moving);
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  EXPECT_EQ(out.reference_time_s, 7.0);
  const Eigen::Isometry3d T_body_lidar = plugin_test::PoseRpyDeg(Eigen::Vector3d(0.0, 0.0, 0.1), 0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    ASSERT_EQ(out.points[i].time_s, 7.0) << i;
    ASSERT_LT((out.points[i].position_m - T_body_lidar * sweep.scan.points[i].position_m).norm(), 1e-12) << i;
  }
}

TEST_F(Fixed3dPluginTest, TimingNoneKeepsPointTimesTheScanHas) {
  plugin_test::ConfigureWith(&plugin(), {{"lidar.timing", std::string("none")}});
  Sweep sweep = MakeSweep(2.0, 0.0, /*clockwise=*/true);
  for (std::size_t i = 0; i < sweep.scan.points.size(); ++i) sweep.scan.points[i].time_s = sweep.true_time_s[i];
  sweep.scan.end_time_s = sweep.true_time_s.back();
  sweep.scan.has_point_time = true;
  const BodyScan out = plugin().Deskew(sweep.scan, EncoderTrack(), plugin_test::StaticBody());
  ASSERT_EQ(out.points.size(), sweep.scan.points.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) ASSERT_EQ(out.points[i].time_s, sweep.true_time_s[i]) << i;
  EXPECT_EQ(out.reference_time_s, sweep.true_time_s.back());
}

TEST_F(Fixed3dPluginTest, TimingIsAzimuthOrNone) {
  try {
    plugin_test::ConfigureWith(&plugin(), {{"lidar.timing", std::string("rosette")}});
    ADD_FAILURE() << "accepted lidar.timing rosette";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("lidar.timing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unimap
