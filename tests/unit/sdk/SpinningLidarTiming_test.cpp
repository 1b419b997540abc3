#include "unimap/SpinningLidarTiming.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

TEST(SpinningLidarTiming, TimesFollowClockwiseAzimuth) {
  // A clockwise 10 Hz head firing every 1 ms starting at azimuth 30 deg.
  RawScan scan;
  scan.start_time_s = 2.0;
  scan.has_point_time = false;
  std::vector<double> truth;
  for (int i = 0; i < 99; ++i) {
    const double t = 1e-3 * i;
    const double azimuth = 30.0 * M_PI / 180.0 - 2.0 * M_PI * 10.0 * t;
    Point p;
    p.position_m = Eigen::Vector3d(5 * std::cos(azimuth), 5 * std::sin(azimuth), 0.3);
    scan.points.push_back(p);
    truth.push_back(2.0 + t);
  }
  SpinningLidarTiming{10.0, true}.AssignPointTimes(&scan);
  EXPECT_TRUE(scan.has_point_time);
  for (std::size_t i = 0; i < truth.size(); ++i) EXPECT_NEAR(scan.points[i].time_s, truth[i], 1e-12) << i;
  EXPECT_NEAR(scan.end_time_s, truth.back(), 1e-12);
}

TEST(SpinningLidarTiming, CounterClockwiseAndEmpty) {
  RawScan scan;
  Point a, b;
  a.position_m = Eigen::Vector3d(1, 0, 0);
  b.position_m = Eigen::Vector3d(0, 1, 0);  // +90 deg counter-clockwise
  scan.points = {a, b};
  SpinningLidarTiming{5.0, false}.AssignPointTimes(&scan);
  EXPECT_NEAR(scan.points[1].time_s, 0.25 / 5.0, 1e-12);
  RawScan empty;
  EXPECT_THROW(SpinningLidarTiming{}.AssignPointTimes(&empty), InputError);
}

}  // namespace
}  // namespace unimap
