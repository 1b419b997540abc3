// Every payload drops and counts returns outside lidar.min_range_m ..
// lidar.max_range_m (inclusive), as configured.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "PluginTestSupport.hpp"
#include "unimap/Errors.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

// Points straight ahead of the LiDAR (azimuth 0: inside every scanner's
// field of view) at the given ranges, stamped within [10, 10.01] s; the
// intensity is the index.
RawScan ScanAtRanges(const std::vector<double>& ranges_m) {
  RawScan scan;
  scan.start_time_s = 10.0;
  scan.end_time_s = 10.01;
  for (std::size_t i = 0; i < ranges_m.size(); ++i) {
    Point p;
    p.position_m = Eigen::Vector3d(ranges_m[i], 0.0, 0.0);
    p.intensity = static_cast<float>(i);
    p.time_s = 10.0 + 0.01 * static_cast<double>(i) / static_cast<double>(ranges_m.size());
    scan.points.push_back(p);
  }
  return scan;
}

class RangeLimitParametersTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    loaded_ = plugin_test::LoadPayload(GetParam());
    encoder_ = plugin_test::ConstantRateEncoder(9.0, 11.0, 0.0, 3.14159, 100.0);
  }
  PayloadPlugin& plugin() { return *loaded_.plugin; }
  // Ranges of the returns that survive deskewing a static body's scan.
  std::vector<double> KeptRanges(const std::vector<double>& ranges_m, std::size_t* dropped) {
    const BodyScan out = plugin().Deskew(ScanAtRanges(ranges_m), encoder_, plugin_test::StaticBody());
    *dropped = out.dropped_out_of_range;
    std::vector<double> kept_ranges;  // the intensity carries the input index
    for (const Point& p : out.points) {
      kept_ranges.push_back(ranges_m.at(static_cast<std::size_t>(p.intensity)));
    }
    return kept_ranges;
  }

  LoadedPlugin loaded_;
  EncoderTrack encoder_;
};

TEST_P(RangeLimitParametersTest, DefaultLimitsDropAndCountOutsideReturns) {
  const ParameterMap defaults = plugin().Defaults().DefaultMap();
  const double min_m = defaults.GetDouble("lidar.min_range_m");
  const double max_m = defaults.GetDouble("lidar.max_range_m");
  // Sensor spec: VLP-16 0.4..100 m, UTM-30LX 0.1..30 m.
  if (GetParam() == "rotating_2d") {
    EXPECT_EQ(min_m, 0.1);
    EXPECT_EQ(max_m, 30.0);
  } else {
    EXPECT_EQ(min_m, 0.4);
    EXPECT_EQ(max_m, 100.0);
  }
  std::size_t dropped = 0;
  const std::vector<double> kept =
      KeptRanges({0.5 * min_m, min_m, 0.5 * (min_m + max_m), max_m, 1.5 * max_m}, &dropped);
  EXPECT_EQ(dropped, 2u);
  EXPECT_EQ(kept, (std::vector<double>{min_m, 0.5 * (min_m + max_m), max_m}));
}

TEST_P(RangeLimitParametersTest, ConfiguredLimitsApply) {
  plugin_test::ConfigureWith(&plugin(), {{"lidar.min_range_m", 1.0}, {"lidar.max_range_m", 5.0}});
  std::size_t dropped = 0;
  const std::vector<double> kept = KeptRanges({0.99, 1.0, 3.0, 5.0, 5.01, 20.0, 0.2}, &dropped);
  EXPECT_EQ(dropped, 4u);
  EXPECT_EQ(kept, (std::vector<double>{1.0, 3.0, 5.0}));
}

TEST_P(RangeLimitParametersTest, LimitsOutOfOrderAreAConfigErrorNamingTheKey) {
  try {
    plugin_test::ConfigureWith(&plugin(), {{"lidar.min_range_m", 8.0}, {"lidar.max_range_m", 5.0}});
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "lidar.max_range_m");
  }
}

INSTANTIATE_TEST_SUITE_P(AllPayloads, RangeLimitParametersTest, ::testing::ValuesIn(plugin_test::PayloadNames()),
                         plugin_test::PayloadTestName);

}  // namespace
}  // namespace unimap
