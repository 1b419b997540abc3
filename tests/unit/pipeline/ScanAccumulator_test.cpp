#include "pipeline/ScanAccumulator.hpp"

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

TEST(ScanAccumulator, CollectsNScansThenResets) {
  ScanAccumulator accumulator(3);
  EXPECT_FALSE(accumulator.Add({Eigen::Vector3f(1, 0, 0)}, {}, Eigen::Vector3f(0, 0, 0)));
  EXPECT_FALSE(accumulator.Add({Eigen::Vector3f(2, 0, 0), Eigen::Vector3f(3, 0, 0)}, {}, Eigen::Vector3f(1, 0, 0)));
  EXPECT_TRUE(accumulator.Add({}, {}, Eigen::Vector3f(2, 0, 0)));
  Eigen::Vector3f origin;
  std::vector<float> intensities;
  const auto points = accumulator.Take(&origin, &intensities);
  EXPECT_EQ(points.size(), 3u);
  EXPECT_EQ(origin, Eigen::Vector3f(1, 0, 0));  // mean sensor position
  EXPECT_EQ(accumulator.count(), 0);
  EXPECT_TRUE(intensities.empty());  // none were given
}

TEST(ScanAccumulator, KeepsIntensitiesOnlyWhenEveryScanHasThem) {
  ScanAccumulator accumulator(2);
  accumulator.Add({Eigen::Vector3f(1, 0, 0)}, {7.0f}, Eigen::Vector3f::Zero());
  accumulator.Add({Eigen::Vector3f(2, 0, 0), Eigen::Vector3f(3, 0, 0)}, {8.0f, 9.0f}, Eigen::Vector3f::Zero());
  Eigen::Vector3f origin;
  std::vector<float> intensities;
  EXPECT_EQ(accumulator.Take(&origin, &intensities).size(), 3u);
  EXPECT_EQ(intensities, (std::vector<float>{7.0f, 8.0f, 9.0f}));
  // One scan without them: the 3D scan has none (they would not line up).
  accumulator.Add({Eigen::Vector3f(1, 0, 0)}, {7.0f}, Eigen::Vector3f::Zero());
  accumulator.Add({Eigen::Vector3f(2, 0, 0)}, {}, Eigen::Vector3f::Zero());
  EXPECT_EQ(accumulator.Take(&origin, &intensities).size(), 2u);
  EXPECT_TRUE(intensities.empty());
  // And the next 3D scan starts afresh.
  accumulator.Add({Eigen::Vector3f(1, 0, 0)}, {5.0f}, Eigen::Vector3f::Zero());
  accumulator.Add({}, {}, Eigen::Vector3f::Zero());
  accumulator.Take(&origin, &intensities);
  EXPECT_EQ(intensities, (std::vector<float>{5.0f}));
}

TEST(ScanAccumulator, KeepsMapOnlyPointsApart) {
  ScanAccumulator accumulator(2);
  EXPECT_FALSE(accumulator.Add({Eigen::Vector3f(1, 0, 0)}, {}, Eigen::Vector3f::Zero(), {Eigen::Vector3f(5, 0, 0)}));
  EXPECT_TRUE(accumulator.Add({Eigen::Vector3f(2, 0, 0)}, {}, Eigen::Vector3f::Zero(), {Eigen::Vector3f(6, 0, 0)}));
  Eigen::Vector3f origin;
  std::vector<float> intensities;
  std::vector<Eigen::Vector3f> map_only;
  const auto points = accumulator.Take(&origin, &intensities, &map_only);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1], Eigen::Vector3f(2, 0, 0));
  ASSERT_EQ(map_only.size(), 2u);
  EXPECT_EQ(map_only[0], Eigen::Vector3f(5, 0, 0));
  // Taking without asking for them drops them with the rest.
  accumulator.Add({}, {}, Eigen::Vector3f::Zero(), {Eigen::Vector3f(7, 0, 0)});
  accumulator.Add({}, {}, Eigen::Vector3f::Zero());
  accumulator.Take(&origin, &intensities);
  accumulator.Add({}, {}, Eigen::Vector3f::Zero());
  accumulator.Add({}, {}, Eigen::Vector3f::Zero());
  accumulator.Take(&origin, &intensities, &map_only);
  EXPECT_TRUE(map_only.empty());
}

}  // namespace
}  // namespace unimap::pipeline
