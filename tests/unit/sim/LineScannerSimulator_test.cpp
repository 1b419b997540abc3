#include "LineScannerSimulator.hpp"

#include <cmath>
#include <variant>

#include <gtest/gtest.h>

#include "SimTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Ranges the scanner must report without noise: the room's analytic wall
// distance from the exact LiDAR pose at each beam's own firing time.
void ExpectAnalyticRanges(const LineScan& line, const test::BoxRoom& room, const MotionQuery& body,
                          const MountQuery& mount, double tolerance) {
  for (std::size_t i = 0; i < line.ranges_m.size(); ++i) {
    const double t = line.start_time_s + static_cast<double>(i) * line.time_increment_s;
    const Eigen::Isometry3d T_world_lidar = body(t) * mount(t);
    const double a = line.angle_min_rad + static_cast<double>(i) * line.angle_increment_rad;
    const Eigen::Vector3d d = T_world_lidar.linear() * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    ASSERT_NEAR(line.ranges_m[i], room.RangeFrom(T_world_lidar.translation(), d), tolerance) << "beam " << i;
  }
}

TEST(LineScannerSimulator, BoxRoomRangesEqualAnalyticWallDistances) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return test::RestingBody(); };
  const MountQuery mount = [](double t) { return test::RotatingMount(t); };
  LineScannerSimulator scanner(world, LidarPoseTrack(body, mount, 0.0), LineScannerPattern{}, LidarNoise{}, 1);
  for (double start : {0.0, 0.025, 0.3}) {
    const io::ScanRecord record = scanner.Simulate(start);
    const LineScan& line = std::get<LineScan>(record);
    ASSERT_EQ(line.ranges_m.size(), 1081u);
    ExpectAnalyticRanges(line, room, body, mount, 2e-6);  // float storage of <= 10 m ranges
  }
  EXPECT_EQ(scanner.rays(), 3u * 1081u);
  EXPECT_EQ(scanner.returns(), 3u * 1081u);
}

TEST(LineScannerSimulator, MovingBodyWithPoseKnotsStaysWithinMicrometers) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MountQuery mount = [](double t) { return test::RotatingMount(t); };
  LineScannerSimulator scanner(world, LidarPoseTrack(test::MovingBody, mount, 1e-3), LineScannerPattern{}, LidarNoise{},
                               1);
  for (double start : {0.5, 1.0, 2.475}) {
    const LineScan line = std::get<LineScan>(scanner.Simulate(start));
    ExpectAnalyticRanges(line, room, test::MovingBody, mount, 5e-6);
  }
}

TEST(LineScannerSimulator, LineHeaderDescribesTheUtm30Pattern) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return test::RestingBody(); };
  LineScannerSimulator scanner(world, LidarPoseTrack(body, body, 0.0), LineScannerPattern{}, LidarNoise{}, 1);
  const LineScan line = std::get<LineScan>(scanner.Simulate(2.0));
  EXPECT_DOUBLE_EQ(line.start_time_s, 2.0);
  EXPECT_NEAR(line.angle_min_rad, -135 * kDeg, 1e-12);
  EXPECT_NEAR(line.angle_increment_rad, 0.25 * kDeg, 1e-12);
  // beam i fires at start + i * period * increment / (2 pi)
  EXPECT_NEAR(line.time_increment_s, 0.025 * 0.25 / 360.0, 1e-15);
  EXPECT_DOUBLE_EQ(scanner.scan_period_s(), 0.025);
  EXPECT_NEAR(scanner.scan_span_s(), 0.025 * 270.0 / 360.0, 1e-15);
  EXPECT_DOUBLE_EQ(line.range_min_m, 0.1);
  EXPECT_DOUBLE_EQ(line.range_max_m, 30.0);
  EXPECT_TRUE(line.intensities.empty());
}

TEST(LineScannerSimulator, OutOfRangeBeamsReportNoReturn) {
  test::BoxRoom room;
  room.size = Eigen::Vector3d(60.0, 6.0, 4.0);  // x walls beyond 30 m from the centre
  room.center = Eigen::Vector3d(0.0, 0.0, 1.0);
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return Eigen::Isometry3d::Identity(); };
  LineScannerPattern pattern;
  pattern.max_range_m = 25.0;
  LineScannerSimulator scanner(world, LidarPoseTrack(body, body, 0.0), pattern, LidarNoise{}, 1);
  const LineScan line = std::get<LineScan>(scanner.Simulate(0.0));
  const std::size_t forward = 540;  // beam along +x: wall at 30 m > 25 m
  EXPECT_TRUE(std::isnan(line.ranges_m[forward]));
  EXPECT_NEAR(line.ranges_m[forward + 360], 3.0, 1e-6);  // +90 deg: side wall at 3 m
}

// Dropout and range noise statistics over 100 lines (108,100 beams): the
// dropout fraction within 5 binomial sigmas, the noise sigma within 5 sqrt(2/N).
TEST(LineScannerSimulator, NoiseAndDropoutsMatchTheirSettings) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  const MotionQuery body = [](double) { return test::RestingBody(); };
  const MountQuery mount = [](double t) { return test::RotatingMount(t); };
  const LidarNoise noise{0.02, 0.1};
  LineScannerSimulator scanner(world, LidarPoseTrack(body, mount, 0.0), LineScannerPattern{}, noise, 99);
  double n = 0, dropped = 0, sum = 0, sum_sq = 0;
  for (int k = 0; k < 100; ++k) {
    const LineScan line = std::get<LineScan>(scanner.Simulate(k * 0.025));
    for (std::size_t i = 0; i < line.ranges_m.size(); ++i) {
      n += 1;
      if (std::isnan(line.ranges_m[i])) {
        dropped += 1;
        continue;
      }
      const double t = line.start_time_s + static_cast<double>(i) * line.time_increment_s;
      const Eigen::Isometry3d T = body(t) * mount(t);
      const double a = line.angle_min_rad + static_cast<double>(i) * line.angle_increment_rad;
      const double e =
          line.ranges_m[i] - room.RangeFrom(T.translation(), T.linear() * Eigen::Vector3d(std::cos(a), std::sin(a), 0));
      sum += e;
      sum_sq += e * e;
    }
  }
  const double p = noise.dropout_probability;
  EXPECT_NEAR(dropped / n, p, 5 * std::sqrt(p * (1 - p) / n));
  const double kept = n - dropped;
  const double var = (sum_sq - sum * sum / kept) / (kept - 1);
  EXPECT_NEAR(var / (noise.range_sigma_m * noise.range_sigma_m), 1.0, 5 * std::sqrt(2.0 / kept));
  EXPECT_NEAR(sum / kept, 0.0, 5 * noise.range_sigma_m / std::sqrt(kept));
  EXPECT_EQ(scanner.rays(), static_cast<std::uint64_t>(n));
  EXPECT_EQ(scanner.returns(), static_cast<std::uint64_t>(kept));
}

TEST(LineScannerSimulator, PatternComesFromThePayloadKeys) {
  ParameterMap p;
  p.Set("lidar.scan_rate_hz", 20.0);
  p.Set("lidar.fov_deg", 180.0);
  p.Set("lidar.beams", std::int64_t{361});
  p.Set("lidar.min_range_m", 0.2);
  p.Set("lidar.max_range_m", 8.0);
  const LineScannerPattern pattern = LineScannerPattern::FromParameters(p);
  EXPECT_DOUBLE_EQ(pattern.scan_rate_hz, 20.0);
  EXPECT_DOUBLE_EQ(pattern.fov_deg, 180.0);
  EXPECT_EQ(pattern.beams, 361);
  EXPECT_DOUBLE_EQ(pattern.min_range_m, 0.2);
  EXPECT_DOUBLE_EQ(pattern.max_range_m, 8.0);
  p = ParameterMap();
  EXPECT_THROW(LineScannerPattern::FromParameters(p), ConfigError);
}

}  // namespace
}  // namespace unimap::sim
