#include "pipeline/SceneScale.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

// A sweep with one return at each of the ranges, along directions that vary
// (the median must not depend on the frame or the direction).
RawScan Sweep(const std::vector<double>& ranges) {
  RawScan scan;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double azimuth = 0.7 * static_cast<double>(i);
    const double elevation = 0.1 * std::sin(static_cast<double>(i));
    Point p;
    p.position_m = ranges[i] * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    scan.points.push_back(p);
  }
  return scan;
}

TEST(SceneScaleTest, MedianOverEveryReturnOfEveryScan) {
  // 1..9 m over two sweeps and a line: the median of the nine is 5 m.
  LineScan line;
  line.range_min_m = 0.5;
  line.range_max_m = 30.0;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Invalid beams are not returns: NaN, infinity, below range_min_m, above range_max_m.
  line.ranges_m = {8.0f, nan, 9.0f, std::numeric_limits<float>::infinity(), 0.2f, 31.0f};
  const std::vector<io::ScanRecord> scans = {io::ScanRecord(Sweep({1.0, 7.0, 3.0})), io::ScanRecord(line),
                                             io::ScanRecord(Sweep({5.0, 2.0, 6.0, 4.0}))};
  const SceneScale scale = MeasureSceneScale(scans);
  EXPECT_EQ(scale.returns, 9u);
  EXPECT_EQ(scale.scans, 3u);
  EXPECT_NEAR(scale.median_range_m, 5.0, 1e-6);
}

TEST(SceneScaleTest, NoReturnsGiveZero) {
  const SceneScale none = MeasureSceneScale({});
  EXPECT_EQ(none.returns, 0u);
  EXPECT_EQ(none.median_range_m, 0.0);
  EXPECT_EQ(SceneVoxel(0.1, none.median_range_m, kMaxVoxelsAcrossScene, 2.0), 0.1);
}

TEST(SceneScaleTest, VoxelIsTheSmallestWholeMultipleSpanningAtMostTheLimit) {
  // 40 voxels of 0.1 m span 4 m.
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 1.4, 40.0, 2.0), 0.1);
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 4.0, 40.0, 2.0), 0.1);   // exactly 40 voxels: kept
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 4.01, 40.0, 2.0), 0.2);  // 40.1: two voxels in one
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 9.18, 40.0, 2.0), 0.3);  // 91.8 -> 3 x (30.6 across)
  EXPECT_DOUBLE_EQ(SceneVoxel(0.3, 10.08, 40.0, 2.0), 0.3);
  EXPECT_DOUBLE_EQ(SceneVoxel(0.3, 25.0, 40.0, 2.0), 0.9);  // ceil(25 / 12) = 3
  // Never beyond the largest voxel allowed (a whole multiple of the platform's).
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 1000.0, 40.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(SceneVoxel(0.3, 1000.0, 40.0, 5.0), 4.8);
  EXPECT_DOUBLE_EQ(SceneVoxel(0.1, 9.18, 40.0, 0.25), 0.2);
  // k = 1 returns the platform's voxel as given, not a rounded copy.
  EXPECT_EQ(SceneVoxel(0.1234567891234, 1.0, 40.0, 2.0), 0.1234567891234);
  // The result spans at most the limit and one multiple less would not.
  for (double r = 0.5; r < 60.0; r += 0.37) {
    const double v = SceneVoxel(0.1, r, 40.0, 2.0);
    EXPECT_LE(r / v, 40.0 + 1e-6) << r;
    if (v > 0.1 + 1e-9) {
      EXPECT_GT(r / (v - 0.1), 40.0) << r;
    }
  }
}

}  // namespace
}  // namespace unimap::pipeline
