#include "calibration/PointGrid.hpp"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

namespace unimap::calibration {
namespace {

TEST(PointGrid, FindsWhatABruteForceSearchFinds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::vector<Eigen::Vector3f> points(5000);
  for (auto& p : points) p = Eigen::Vector3f(u(rng), u(rng), u(rng));
  const PointGrid grid(points, 0.4);
  for (const double radius : {0.1, 0.4}) {
    for (int q = 0; q < 200; ++q) {
      const Eigen::Vector3f centre(u(rng), u(rng), u(rng));
      std::vector<std::uint32_t> found, expected;
      grid.ForEachWithin(centre, radius, [&](std::uint32_t i) { found.push_back(i); });
      for (std::uint32_t i = 0; i < points.size(); ++i) {
        if ((points[i] - centre).squaredNorm() <= static_cast<float>(radius * radius)) expected.push_back(i);
      }
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected);
    }
  }
}

}  // namespace
}  // namespace unimap::calibration
