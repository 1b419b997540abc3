#include "pipeline/ScanAccumulator.hpp"

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

TEST(ScanAccumulator, CollectsNScansThenResets) {
  ScanAccumulator accumulator(3);
  EXPECT_FALSE(accumulator.Add({Eigen::Vector3f(1, 0, 0)}, Eigen::Vector3f(0, 0, 0)));
  EXPECT_FALSE(accumulator.Add({Eigen::Vector3f(2, 0, 0), Eigen::Vector3f(3, 0, 0)}, Eigen::Vector3f(1, 0, 0)));
  EXPECT_TRUE(accumulator.Add({}, Eigen::Vector3f(2, 0, 0)));
  Eigen::Vector3f origin;
  const auto points = accumulator.Take(&origin);
  EXPECT_EQ(points.size(), 3u);
  EXPECT_EQ(origin, Eigen::Vector3f(1, 0, 0));  // mean sensor position
  EXPECT_EQ(accumulator.count(), 0);
}

}  // namespace
}  // namespace unimap::pipeline
