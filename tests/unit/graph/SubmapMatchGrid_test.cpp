#include "graph/SubmapMatchGrid.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::graph {
namespace {

std::vector<Eigen::Vector3f> RandomPoints(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> x(-2.0f, 3.0f);
  std::uniform_real_distribution<float> z(0.0f, 1.0f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < n; ++i) points.emplace_back(x(rng), x(rng), z(rng));
  return points;
}

// Level-0 value by brute force: the kernel of the point-to-cell-box distance.
int BruteForceValue(const SubmapMatchGrid& grid, const std::vector<Eigen::Vector3f>& points, double kernel_m,
                    const Eigen::Vector3i& cell) {
  const double r = grid.resolution();
  const Eigen::Vector3d lo = grid.origin() + cell.cast<double>() * r;
  int best = 0;
  for (const auto& p : points) {
    const Eigen::Vector3d q = p.cast<double>();
    const Eigen::Vector3d gap = (lo - q).cwiseMax(q - (lo + Eigen::Vector3d::Constant(r))).cwiseMax(0.0);
    const double score = 1.0 - gap.norm() / kernel_m;
    if (score > 0.0) best = std::max(best, static_cast<int>(score * 255.0 + 0.5));
  }
  return best;
}

TEST(SubmapMatchGridTest, BaseLevelIsTheKernelOfTheDistanceToTheCell) {
  const auto points = RandomPoints(60, 1);
  const double kernel_m = 0.3;
  const SubmapMatchGrid grid(points, 0.25, kernel_m, 4);
  std::mt19937_64 rng(2);
  for (int k = 0; k < 400; ++k) {
    const Eigen::Vector3i cell(std::uniform_int_distribution<int>(0, grid.dims().x() - 1)(rng),
                               std::uniform_int_distribution<int>(0, grid.dims().y() - 1)(rng),
                               std::uniform_int_distribution<int>(0, grid.dims().z() - 1)(rng));
    EXPECT_NEAR(grid.Value(0, cell), BruteForceValue(grid, points, kernel_m, cell), 1) << cell.transpose();
  }
  for (const auto& p : points) EXPECT_EQ(grid.Value(0, grid.CellOf(p.cast<double>())), 255);
  EXPECT_EQ(grid.Value(0, Eigen::Vector3i(-1, 0, 0)), 0);
  EXPECT_EQ(grid.Value(0, grid.dims()), 0);
}

TEST(SubmapMatchGridTest, PooledLevelsAreMaximaOverXyWindows) {
  const auto points = RandomPoints(40, 3);
  const SubmapMatchGrid grid(points, 0.2, 0.25, 4);
  ASSERT_EQ(grid.levels(), 4);
  // Windows starting below the points (the padding) included.
  for (int level = 1; level < grid.levels(); ++level) {
    const int size = 1 << level;
    for (int x = 0; x < grid.dims().x(); x += 3) {
      for (int y = 0; y < grid.dims().y(); y += 2) {
        for (int z = 0; z < grid.dims().z(); ++z) {
          int expected = 0;
          for (int dx = 0; dx < size; ++dx) {
            for (int dy = 0; dy < size; ++dy) expected = std::max<int>(expected, grid.Value(0, {x + dx, y + dy, z}));
          }
          ASSERT_EQ(grid.Value(level, {x, y, z}), expected) << level << " " << x << " " << y << " " << z;
        }
      }
    }
  }
  // The padding holds the low-side windows: a point on the lowest data cell
  // is seen from 2^(levels-1) - 1 cells before it.
  const Eigen::Vector3i lowest = grid.CellOf(points.front().cast<double>());
  EXPECT_GE(lowest.x(), (1 << (grid.levels() - 1)) - 1);
  EXPECT_GE(lowest.y(), (1 << (grid.levels() - 1)) - 1);
}

TEST(SubmapMatchGridTest, TooLargeABoxIsAnInputError) {
  const std::vector<Eigen::Vector3f> far = {Eigen::Vector3f::Zero(), Eigen::Vector3f(4000.0f, 4000.0f, 50.0f)};
  EXPECT_THROW(SubmapMatchGrid(far, 0.25, 0.3, 4), InputError);
}

}  // namespace
}  // namespace unimap::graph
