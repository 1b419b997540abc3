#include "unimap/LineScan.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

LineScan Hokuyo() {
  LineScan line;
  line.start_time_s = 100.0;
  line.angle_min_rad = -135.0 * M_PI / 180.0;
  line.angle_increment_rad = 0.25 * M_PI / 180.0;
  line.time_increment_s = 0.025 / 1440.0;
  line.range_min_m = 0.1;
  line.range_max_m = 30.0;
  line.ranges_m.assign(1081, 2.0f);
  return line;
}

TEST(LineScanToRawScan, BeamGeometryAndTiming) {
  LineScan line = Hokuyo();
  line.ranges_m[540] = 3.0f;  // straight ahead
  const LineScanConversion out = LineScanToRawScan(line);
  ASSERT_EQ(out.scan.points.size(), 1081u);
  EXPECT_EQ(out.dropped, 0u);
  EXPECT_TRUE(out.scan.points[540].position_m.isApprox(Eigen::Vector3d(3, 0, 0), 1e-6));
  EXPECT_TRUE(out.scan.points[0].position_m.isApprox(
      Eigen::Vector3d(2 * std::cos(-3 * M_PI / 4), 2 * std::sin(-3 * M_PI / 4), 0), 1e-6));
  EXPECT_DOUBLE_EQ(out.scan.points[1080].time_s, 100.0 + 1080 * line.time_increment_s);
  EXPECT_DOUBLE_EQ(out.scan.end_time_s, out.scan.points[1080].time_s);
}

TEST(LineScanToRawScan, DropsInvalidBeamsAndRejectsMalformedLines) {
  LineScan line = Hokuyo();
  line.ranges_m[0] = std::nanf("");
  line.ranges_m[1] = 0.05f;
  line.ranges_m[2] = 31.0f;
  line.ranges_m[3] = std::numeric_limits<float>::infinity();
  const LineScanConversion out = LineScanToRawScan(line);
  EXPECT_EQ(out.dropped, 4u);
  EXPECT_EQ(out.scan.points.size(), 1077u);
  line.intensities.assign(3, 1.0f);
  EXPECT_THROW(LineScanToRawScan(line), InputError);
  EXPECT_THROW(LineScanToRawScan(LineScan{}), InputError);
}

}  // namespace
}  // namespace unimap
