#include "map/KeyBox.hpp"

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using V3i = Eigen::Vector3i;

TEST(KeyBox, EmptyBoxHasNoCellsAndContainsNothing) {
  const KeyBox empty;
  EXPECT_TRUE(empty.IsEmpty());
  EXPECT_EQ(empty.CellCount(), 0u);
  EXPECT_FALSE(empty.Contains(V3i(0, 0, 0)));
  EXPECT_TRUE(KeyBox(V3i(5, 0, 0), V3i(4, 9, 9)).IsEmpty());
  EXPECT_TRUE(empty.Inflated(3).IsEmpty());
  EXPECT_EQ(KeyBox(V3i(5, 0, 0), V3i(4, 9, 9)), empty);
}

TEST(KeyBox, BoundsAreInclusive) {
  const KeyBox box(V3i(10, 20, 30), V3i(12, 20, 33));
  EXPECT_EQ(box.Dims(), V3i(3, 1, 4));
  EXPECT_EQ(box.CellCount(), 12u);
  EXPECT_TRUE(box.Contains(V3i(10, 20, 30)));
  EXPECT_TRUE(box.Contains(V3i(12, 20, 33)));
  EXPECT_FALSE(box.Contains(V3i(13, 20, 33)));
  EXPECT_FALSE(box.Contains(V3i(11, 21, 31)));
}

TEST(KeyBox, ExtendInflateAndIntersect) {
  KeyBox box;
  box.Extend(V3i(1, 2, 3));
  EXPECT_EQ(box, KeyBox(V3i(1, 2, 3), V3i(1, 2, 3)));
  box.Extend(V3i(-1, 5, 3));
  EXPECT_EQ(box, KeyBox(V3i(-1, 2, 3), V3i(1, 5, 3)));
  box.Extend(KeyBox());
  EXPECT_EQ(box, KeyBox(V3i(-1, 2, 3), V3i(1, 5, 3)));
  EXPECT_EQ(box.Inflated(2), KeyBox(V3i(-3, 0, 1), V3i(3, 7, 5)));
  const KeyBox other(V3i(0, 4, 0), V3i(9, 9, 9));
  EXPECT_EQ(box.Intersection(other), KeyBox(V3i(0, 4, 3), V3i(1, 5, 3)));
  EXPECT_TRUE(box.Intersection(KeyBox(V3i(7, 7, 7), V3i(8, 8, 8))).IsEmpty());
  EXPECT_TRUE(box.Inflated(2).Contains(box));
  EXPECT_FALSE(box.Contains(box.Inflated(1)));
  EXPECT_TRUE(box.Contains(KeyBox()));
  EXPECT_NE(box, other);
}

}  // namespace
}  // namespace unimap::map
