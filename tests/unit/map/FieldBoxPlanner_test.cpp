#include "map/FieldBoxPlanner.hpp"

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using V3i = Eigen::Vector3i;

DistanceMapOptions Options() {
  DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.max_range_m = 15.0;
  options.clamp_distance_m = 1.0;
  options.recenter_fraction = 0.25;
  options.growth_margin_m = 0.5;
  return options;
}

TEST(FieldBoxPlanner, SensorBoxSpansMaxRangeEachWay) {
  const FieldBoxPlanner planner(Options(), 0.1);
  EXPECT_EQ(planner.range_cells(), 150);
  EXPECT_EQ(planner.clamp_cells(), 10);
  const KeyBox box = planner.SensorBox(V3i(1000, 2000, 3000));
  EXPECT_EQ(box, KeyBox(V3i(850, 1850, 2850), V3i(1150, 2150, 3150)));
}

// A tunnel 5.8 m wide and 7 m high running along x through the sensor box:
// the field spans 30 m along x but only the cross-section plus the clamp.
TEST(FieldBoxPlanner, FieldBoxIsClippedToTheOccupiedExtent) {
  const FieldBoxPlanner planner(Options(), 0.1);
  const V3i center(0, 0, 0);
  const KeyBox sensor = planner.SensorBox(center);
  const KeyBox tunnel(V3i(-400, -29, -10), V3i(400, 28, 59));
  bool shrunk = false;
  const KeyBox field = planner.FieldBox(tunnel.Intersection(sensor), sensor, center, &shrunk);
  EXPECT_FALSE(shrunk);
  EXPECT_EQ(field, KeyBox(V3i(-150, -39, -20), V3i(150, 38, 69)));
  EXPECT_EQ(field.CellCount(), 301u * 78u * 90u);
  EXPECT_TRUE(planner.FieldBox(KeyBox(), sensor, center, nullptr).IsEmpty());
}

TEST(FieldBoxPlanner, OversizedBoxesShrinkAboutTheCenter) {
  DistanceMapOptions options = Options();
  options.max_edt_cells = 1000000;
  const FieldBoxPlanner planner(options, 0.1);
  const V3i center(5, 5, 5);
  const KeyBox sensor = planner.SensorBox(center);
  bool shrunk = false;
  const KeyBox field = planner.FieldBox(sensor, sensor, center, &shrunk);
  EXPECT_TRUE(shrunk);
  EXPECT_LE(field.CellCount(), 1000000u);
  EXPECT_GT(field.CellCount(), 500000u);
  EXPECT_TRUE(field.Contains(center));
  EXPECT_EQ(field.max() - center, center - field.min());
}

TEST(FieldBoxPlanner, RecenterWhenTheSensorLeavesTheCentralRegion) {
  const FieldBoxPlanner planner(Options(), 0.1);  // threshold 3.75 m = 37.5 voxels
  EXPECT_FALSE(planner.NeedsRecenter(V3i(0, 0, 0), V3i(37, -37, 37)));
  EXPECT_TRUE(planner.NeedsRecenter(V3i(0, 0, 0), V3i(0, 38, 0)));
  EXPECT_TRUE(planner.NeedsRecenter(V3i(100, 0, 0), V3i(62, 0, 0)));
}

TEST(FieldBoxPlanner, OccupiedExtentGrowsWithMarginOnlyForNewEndpoints) {
  const FieldBoxPlanner planner(Options(), 0.1);  // margin 5 voxels
  const KeyBox sensor = planner.SensorBox(V3i(0, 0, 0));
  const KeyBox occupied(V3i(-10, -10, -10), V3i(10, 10, 10));
  EXPECT_EQ(planner.GrownOccupied(occupied, KeyBox(V3i(-3, 0, 0), V3i(10, 2, 2)), sensor), occupied);
  EXPECT_EQ(planner.GrownOccupied(occupied, KeyBox(), sensor), occupied);
  EXPECT_EQ(planner.GrownOccupied(occupied, KeyBox(V3i(0, 0, 0), V3i(20, 0, 0)), sensor),
            KeyBox(V3i(-15, -15, -15), V3i(25, 15, 15)));
  // Endpoints beyond the sensor box do not grow it past the sensor box.
  EXPECT_EQ(planner.GrownOccupied(occupied, KeyBox(V3i(0, 0, 0), V3i(400, 0, 0)), sensor),
            KeyBox(V3i(-15, -15, -15), V3i(150, 15, 15)));
}

}  // namespace
}  // namespace unimap::map
