#include "SpinningLidarSimulator.hpp"

#include <cmath>
#include <variant>

#include <gtest/gtest.h>

#include "SimTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

SpinningLidarPattern Vlp16(double azimuth_resolution_deg) {
  SpinningLidarPattern p;
  p.azimuth_resolution_deg = azimuth_resolution_deg;
  return p;
}

// Every point: its range equals the analytic wall distance along its own
// direction from the exact LiDAR pose at its own time; its time, azimuth and
// ring follow the firing order.
TEST(SpinningLidarSimulator, BoxRoomPointsLieOnTheWallsInFiringOrder) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MountQuery mount = [](double t) { return test::RotatingMount(t); };
  SpinningLidarSimulator lidar(world, LidarPoseTrack(test::MovingBody, mount, 1e-3), Vlp16(1.0), LidarNoise{}, 1);
  ASSERT_EQ(lidar.firings(), 360u);
  const double start = 0.7;
  const RawScan scan = std::get<RawScan>(lidar.Simulate(start));
  ASSERT_EQ(scan.points.size(), 360u * 16u);
  EXPECT_TRUE(scan.has_point_time);
  EXPECT_DOUBLE_EQ(scan.start_time_s, start);
  EXPECT_NEAR(scan.end_time_s, start + 359.0 / 3600.0, 1e-12);
  for (std::size_t n = 0; n < scan.points.size(); ++n) {
    const Point& p = scan.points[n];
    const std::size_t j = n / 16, k = n % 16;
    ASSERT_EQ(p.ring, k);
    ASSERT_NEAR(p.time_s, start + static_cast<double>(j) / 3600.0, 1e-12);
    const double range = p.position_m.norm();
    const Eigen::Vector3d d_lidar = p.position_m / range;
    // Elevation of ring k: -15 + 2 k deg; azimuth -j deg (clockwise).
    ASSERT_NEAR(std::asin(d_lidar.z()), (-15.0 + 2.0 * static_cast<double>(k)) * kDeg, 1e-9);
    ASSERT_NEAR(std::remainder(std::atan2(d_lidar.y(), d_lidar.x()) + static_cast<double>(j) * kDeg, 2 * M_PI), 0.0,
                1e-9);
    const Eigen::Isometry3d T = test::MovingBody(p.time_s) * mount(p.time_s);
    ASSERT_NEAR(range, room.RangeFrom(T.translation(), T.linear() * d_lidar), 5e-6) << n;
    ASSERT_GT(p.intensity, 0.0f);
  }
}

TEST(SpinningLidarSimulator, CounterClockwiseHeadsIncreaseAzimuth) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return test::RestingBody(); };
  SpinningLidarPattern pattern = Vlp16(2.0);
  pattern.clockwise = false;
  pattern.rings = 1;
  SpinningLidarSimulator lidar(world,
                               LidarPoseTrack(
                                   body, [](double) { return Eigen::Isometry3d::Identity(); }, 0.0),
                               pattern, LidarNoise{}, 1);
  const RawScan scan = std::get<RawScan>(lidar.Simulate(0.0));
  ASSERT_EQ(scan.points.size(), 180u);
  EXPECT_NEAR(std::atan2(scan.points[10].position_m.y(), scan.points[10].position_m.x()), 20.0 * kDeg, 1e-9);
  EXPECT_NEAR(scan.points[10].position_m.z(), 0.0, 1e-12);  // one ring: mean elevation 0
  EXPECT_DOUBLE_EQ(lidar.scan_period_s(), 0.1);
}

TEST(SpinningLidarSimulator, DropoutsRemovePoints) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return test::RestingBody(); };
  SpinningLidarSimulator lidar(world, LidarPoseTrack(body, body, 0.0), Vlp16(0.4), LidarNoise{0.0, 0.25}, 5);
  double kept = 0, fired = 0;
  for (int k = 0; k < 10; ++k) {
    kept += static_cast<double>(std::get<RawScan>(lidar.Simulate(0.1 * k)).points.size());
    fired += 900.0 * 16.0;
  }
  EXPECT_EQ(lidar.rays(), static_cast<std::uint64_t>(fired));
  EXPECT_EQ(lidar.returns(), static_cast<std::uint64_t>(kept));
  EXPECT_NEAR(1.0 - kept / fired, 0.25, 5 * std::sqrt(0.25 * 0.75 / fired));
}

TEST(SpinningLidarSimulator, PatternComesFromThePayloadKeys) {
  ParameterMap p;
  p.Set("lidar.rings", std::int64_t{32});
  p.Set("lidar.vertical_fov_deg", std::vector<double>{-30.0, 10.0});
  p.Set("lidar.spin_rate_hz", 20.0);
  p.Set("lidar.clockwise", false);
  p.Set("lidar.min_range_m", 1.0);
  p.Set("lidar.max_range_m", 80.0);
  const SpinningLidarPattern pattern = SpinningLidarPattern::FromParameters(p, 0.2);
  EXPECT_EQ(pattern.rings, 32);
  EXPECT_DOUBLE_EQ(pattern.vertical_fov_min_deg, -30.0);
  EXPECT_DOUBLE_EQ(pattern.vertical_fov_max_deg, 10.0);
  EXPECT_DOUBLE_EQ(pattern.spin_rate_hz, 20.0);
  EXPECT_FALSE(pattern.clockwise);
  EXPECT_DOUBLE_EQ(pattern.azimuth_resolution_deg, 0.2);
  p.Set("lidar.rings", 3.5);
  EXPECT_THROW(SpinningLidarPattern::FromParameters(p, 0.2), ConfigError);
}

}  // namespace
}  // namespace unimap::sim
