#include "pipeline/ScanMatcher.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "map/SurfaceDistanceLayer.hpp"

namespace unimap::pipeline {
namespace {

using V3 = Eigen::Vector3f;

// A 10 x 6 x 3 m box (floor and four walls) every 10 cm.
std::vector<V3> Box() {
  std::vector<V3> points;
  for (float x = -5.0f; x <= 5.0f; x += 0.1f) {
    for (float y = -3.0f; y <= 3.0f; y += 0.1f) points.emplace_back(x, y, 0.0f);
    for (float z = 0.0f; z <= 3.0f; z += 0.1f) {
      points.emplace_back(x, -3.0f, z);
      points.emplace_back(x, 3.0f, z);
    }
  }
  for (float y = -3.0f; y <= 3.0f; y += 0.1f) {
    for (float z = 0.0f; z <= 3.0f; z += 0.1f) {
      points.emplace_back(-5.0f, y, z);
      points.emplace_back(5.0f, y, z);
    }
  }
  return points;
}

std::shared_ptr<const map::DistanceField> BoxField() {
  map::DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.clamp_distance_m = 0.5;
  map::SurfaceDistanceLayer layer(options);
  layer.Insert(Box(), V3(0, 0, 1.5f));
  return layer.Export(V3::Zero(), 0.0, 1);
}

// The box seen from its centre at 1.5 m (body = map shifted), every 4th
// point, plus a surface the map has not seen: a wall 1 m past the +x wall.
std::vector<V3> ScanWithUnmappedWall(int* unmapped) {
  std::vector<V3> scan;
  const std::vector<V3> box = Box();
  for (std::size_t i = 0; i < box.size(); i += 4) scan.push_back(box[i] - V3(0, 0, 1.5f));
  *unmapped = 0;
  for (float y = -1.0f; y <= 1.0f; y += 0.1f) {
    for (float z = 0.5f; z <= 2.5f; z += 0.1f, ++*unmapped) scan.emplace_back(6.0f, y, z - 1.5f);
  }
  return scan;
}

LocalizerOptions Options() {
  LocalizerOptions o;
  o.max_predicted_distance_m = 0.15;  // 1.5 voxels
  o.sweep_gate_sigmas = 3.0;
  o.gpf.voxel_size_m = 0.0;  // every point reaches the gate
  o.gpf.max_points = 0;
  return o;
}

Eigen::Isometry3d AtCenter() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0, 0, 1.5);
  return T;
}

matching::Matrix6d Covariance(double sigma_m, double sigma_rad) {
  matching::Matrix6d c = matching::Matrix6d::Zero();
  c.diagonal().head<3>().setConstant(sigma_m * sigma_m);
  c.diagonal().tail<3>().setConstant(sigma_rad * sigma_rad);
  return c;
}

// A line scan (ScanWithUnmappedWall) matched at the centre with the given
// covariances; *unmapped receives how many of its points see no map.
ScanMatchResult MatchLine(const matching::Matrix6d& predicted, const matching::Matrix6d& map_relative, int* unmapped) {
  const std::vector<V3> scan = ScanWithUnmappedWall(unmapped);
  ScanMatcher matcher(Options());
  return matcher.Match(BoxField(), AtCenter(), predicted, map_relative, scan, true);
}

TEST(ScanMatcher, ConfidentSweepLeavesOutPointsPastTheMap) {
  int unmapped = 0;
  const std::vector<V3> scan = ScanWithUnmappedWall(&unmapped);
  ScanMatcher matcher(Options());
  const ScanMatchResult r =
      matcher.Match(BoxField(), AtCenter(), Covariance(0.01, 0.001), Covariance(0.01, 0.001), scan, false);
  ASSERT_TRUE(r.match.ok) << r.match.reason;
  // The unmapped wall (1 m from the map, beyond the 0.15 + 3 x 0.01 m +
  // range x 0.003 gate) is left out, the box's own points are measured.
  EXPECT_EQ(r.match.points_unseen, unmapped);
  EXPECT_LT(r.match.posterior_mean.head<3>().norm(), 0.05);
}

TEST(ScanMatcher, UncertainSweepKeepsItsPoints) {
  int unmapped = 0;
  const std::vector<V3> scan = ScanWithUnmappedWall(&unmapped);
  ScanMatcher matcher(Options());
  // Position sigma 0.15 m (below the wide search's 2 voxels): the gate is
  // 0.15 + 0.45 m, more than the field's 0.5 m clamp, so nothing is left out.
  const ScanMatchResult r =
      matcher.Match(BoxField(), AtCenter(), Covariance(0.15, 0.01), Covariance(0.15, 0.01), scan, false);
  ASSERT_TRUE(r.match.ok) << r.match.reason;
  EXPECT_FALSE(r.searched);
  EXPECT_EQ(r.match.points_unseen, 0);
}

TEST(ScanMatcher, LineGateDoesNotWidenWithPositionSigma) {
  int unmapped = 0;
  // Position sigma 0.15 m widens a sweep's gate past the clamp (above), not
  // a line's: with 0.0001 rad its gate is 0.15 m + range x 0.0003, under
  // 0.16 m at the unmapped wall's 6.0-6.2 m, which reads 0.5 m (the clamp).
  const ScanMatchResult r = MatchLine(Covariance(0.15, 0.0001), Covariance(0.15, 0.0001), &unmapped);
  ASSERT_TRUE(r.match.ok) << r.match.reason;
  EXPECT_EQ(r.match.points_unseen, unmapped);
}

TEST(ScanMatcher, LineGateWidensWithRangeTimesRotationSigma) {
  int unmapped = 0;
  // Rotation sigma 0.03 rad moves a point 6 m away by 0.18 m per sigma: the
  // gate there is 0.15 + 3 x 0.18 = 0.69 m, past the field's 0.5 m clamp, so
  // the unmapped wall is measured; the box's own points were anyway.
  const ScanMatchResult r = MatchLine(Covariance(0.001, 0.03), Covariance(0.001, 0.03), &unmapped);
  ASSERT_TRUE(r.match.ok) << r.match.reason;
  EXPECT_EQ(r.match.points_unseen, 0);
}

TEST(ScanMatcher, GateReadsThePoseUncertaintyRelativeToTheMap) {
  int unmapped = 0;
  // The same 0.03 rad as above, but all of it the start's, which the map
  // shares (relative to the map 0.0001 rad): the gate stays at 0.15 m plus
  // millimetres and the unmapped wall is left out.
  const ScanMatchResult r = MatchLine(Covariance(0.001, 0.03), Covariance(0.001, 0.0001), &unmapped);
  ASSERT_TRUE(r.match.ok) << r.match.reason;
  EXPECT_EQ(r.match.points_unseen, unmapped);
}

TEST(ScanMatcher, NoGateMeasuresEveryPoint) {
  int unmapped = 0;
  const std::vector<V3> scan = ScanWithUnmappedWall(&unmapped);
  LocalizerOptions o = Options();
  o.max_predicted_distance_m = 0.0;
  ScanMatcher matcher(o);
  EXPECT_EQ(matcher.Match(BoxField(), AtCenter(), Covariance(0.01, 0.001), Covariance(0.01, 0.001), scan, false)
                .match.points_unseen,
            0);
  EXPECT_EQ(matcher.Match(BoxField(), AtCenter(), Covariance(0.01, 0.001), Covariance(0.01, 0.001), scan, true)
                .match.points_unseen,
            0);
}

}  // namespace
}  // namespace unimap::pipeline
