#include "map/CoarseField.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

// A fine field (0.1 m cells, 40 x 40 x 40 from the origin, clamp 0.5 m)
// whose surface is the two cells (5, 5, 5) and (30, 12, 20).
DistanceField TwoSurfaceCells() {
  const Eigen::Vector3i dims(40, 40, 40);
  const std::vector<Eigen::Vector3i> surface = {{5, 5, 5}, {30, 12, 20}};
  std::vector<std::uint16_t> cells;
  for (int x = 0; x < dims.x(); ++x) {
    for (int y = 0; y < dims.y(); ++y) {
      for (int z = 0; z < dims.z(); ++z) {
        float best = 1e9f;
        for (const Eigen::Vector3i& s : surface)
          best = std::min(best, 0.1f * (Eigen::Vector3i(x, y, z) - s).cast<float>().norm());
        cells.push_back(DistanceField::Quantise(best, 0.5f));
      }
    }
  }
  return DistanceField(V3::Zero(), dims, 0.1f, 0.5f, std::move(cells), 4);
}

TEST(CoarseField, ExactDistancesToTheCoarseSurfaceCellsUpToTheClamp) {
  const auto coarse = CoarsenField(TwoSurfaceCells(), 4, 2.0f);
  EXPECT_FLOAT_EQ(coarse->resolution(), 0.4f);
  EXPECT_EQ(coarse->dims(), Eigen::Vector3i(10, 10, 10));
  EXPECT_EQ(coarse->sequence(), 4u);
  // Surface cells: (1, 1, 1) and (7, 3, 5) of the coarse grid.
  const Eigen::Vector3i a(1, 1, 1), b(7, 3, 5);
  for (int x = 0; x < 10; ++x) {
    for (int y = 0; y < 10; ++y) {
      for (int z = 0; z < 10; ++z) {
        const Eigen::Vector3i c(x, y, z);
        const float truth = std::min(2.0f, 0.4f * std::min((c - a).cast<float>().norm(), (c - b).cast<float>().norm()));
        ASSERT_NEAR(coarse->CellDistance(c), truth, 1e-4f) << c.transpose();
      }
    }
  }
}

TEST(CoarseField, AnEmptyFieldStaysEmpty) {
  const auto coarse = CoarsenField(DistanceField(0.5f, 9), 4, 2.0f);
  EXPECT_EQ(coarse->CellCount(), 0u);
  EXPECT_EQ(coarse->Distance(V3::Zero()), 2.0f);
}

}  // namespace
}  // namespace unimap::map
