#include "SurfaceSampler.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "BoxPrimitive.hpp"
#include "SimTestSupport.hpp"
#include "SpherePrimitive.hpp"
#include "TrajectoryViewpoints.hpp"
#include "WaypointTrajectory.hpp"

namespace unimap::sim {
namespace {

// Which face of the room a point lies on: 2 * axis + (1 for the + side), -1 for none.
int FaceOf(const test::BoxRoom& room, const Eigen::Vector3d& p) {
  for (int j = 0; j < 3; ++j) {
    for (int side = 0; side < 2; ++side) {
      const double wall = room.center[j] + (side == 1 ? 0.5 : -0.5) * room.size[j];
      if (std::abs(p[j] - wall) < 1e-9) return 2 * j + side;
    }
  }
  return -1;
}

std::vector<Eigen::Vector3d> RoomViewpoints() {
  return {Eigen::Vector3d(1.0, 0.0, 1.5), Eigen::Vector3d(-2.0, 1.5, 0.5), Eigen::Vector3d(4.5, -2.0, 3.0)};
}

TEST(SurfaceSampler, FibonacciSphereIsUnitAndBalanced) {
  const auto directions = SurfaceSampler::FibonacciSphere(20000);
  ASSERT_EQ(directions.size(), 20000u);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int up = 0;
  for (const Eigen::Vector3d& d : directions) {
    ASSERT_NEAR(d.norm(), 1.0, 1e-12);
    sum += d;
    up += d.z() > 0.0 ? 1 : 0;
  }
  // The spiral's z values are symmetric: exactly half point up, and the mean is ~0.
  EXPECT_EQ(up, 10000);
  EXPECT_LT((sum / 20000.0).norm(), 1e-3);
  // Even spread: every one of the 6 axis directions has a ray within 1.5 deg
  // (the mean spacing of 20000 rays is ~1.4 deg).
  for (int j = 0; j < 3; ++j) {
    for (const double sign : {-1.0, 1.0}) {
      double best = -1.0;
      for (const Eigen::Vector3d& d : directions) best = std::max(best, sign * d[j]);
      EXPECT_GT(best, std::cos(1.5 * M_PI / 180.0)) << "axis " << j << " sign " << sign;
    }
  }
}

TEST(SurfaceSampler, BoxRoomFromInsideGivesPointsOnAllSixFacesOnly) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  SurfaceSamplerOptions options;
  options.directions_per_viewpoint = 5000;
  const std::vector<Eigen::Vector3d> points = SurfaceSampler(world, options).Sample(RoomViewpoints());
  std::array<int, 6> per_face{};
  for (const Eigen::Vector3d& p : points) {
    ASSERT_LT(world.SurfaceDistance(p), 1e-6) << p.transpose();
    const int face = FaceOf(room, p);
    ASSERT_GE(face, 0) << "not on a face: " << p.transpose();
    ++per_face[static_cast<std::size_t>(face)];
  }
  for (int f = 0; f < 6; ++f) EXPECT_GT(per_face[static_cast<std::size_t>(f)], 100) << "face " << f;
}

TEST(SurfaceSampler, KeepsOnePointPerVoxelAndMoreRaysFillMoreVoxels) {
  const test::BoxRoom room;
  const World world = room.MakeWorld();
  SurfaceSamplerOptions options;
  options.directions_per_viewpoint = 20000;
  options.voxel_m = 0.2;
  const std::vector<Eigen::Vector3d> points = SurfaceSampler(world, options).Sample(RoomViewpoints());
  std::set<std::tuple<long, long, long>> voxels;
  for (const Eigen::Vector3d& p : points) {
    const double inv = 1.0 / 0.2;  // as the sampler computes voxel indices
    const auto key = std::make_tuple(std::lround(std::floor(p.x() * inv)), std::lround(std::floor(p.y() * inv)),
                                     std::lround(std::floor(p.z() * inv)));
    EXPECT_TRUE(voxels.insert(key).second) << "two points in one voxel at " << p.transpose();
  }
  // The room's surface is 2 (10 x 6 + 10 x 4 + 6 x 4) = 248 m^2: at most
  // ~2 * 248 / 0.04 voxels (a face on a voxel boundary may fill two layers).
  EXPECT_LT(points.size(), 2u * 6200u);
  options.directions_per_viewpoint = 2000;
  EXPECT_LT(SurfaceSampler(world, options).Sample(RoomViewpoints()).size(), points.size());
}

TEST(SurfaceSampler, ResultDoesNotDependOnTheThreadCount) {
  const test::BoxRoom room;
  World world;
  world.Add(std::make_unique<BoxPrimitive>(room.center, room.size));
  world.Add(std::make_unique<SpherePrimitive>(Eigen::Vector3d(2.0, 1.0, 1.0), 0.7));
  world.Build();
  std::vector<Eigen::Vector3d> viewpoints;
  for (int i = 0; i < 7; ++i) viewpoints.emplace_back(-3.0 + i, -1.0 + 0.3 * i, 0.5 + 0.2 * i);
  SurfaceSamplerOptions options;
  options.directions_per_viewpoint = 3000;
  options.threads = 1;
  const auto one = SurfaceSampler(world, options).Sample(viewpoints);
  options.threads = 3;
  const auto three = SurfaceSampler(world, options).Sample(viewpoints);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], three[i]) << "point " << i;
  for (const Eigen::Vector3d& p : one) ASSERT_LT(world.SurfaceDistance(p), 1e-6);
}

TEST(SurfaceSampler, RangeLimitsAreRespected) {
  const test::BoxRoom room;  // from its centre the nearest wall is 2 m away (z), the farthest corner ~6.2 m
  const World world = room.MakeWorld();
  SurfaceSamplerOptions options;
  options.directions_per_viewpoint = 4000;
  options.max_range_m = 1.9;
  EXPECT_TRUE(SurfaceSampler(world, options).Sample({room.center}).empty());
  options.max_range_m = 3.5;
  options.min_range_m = 2.5;
  const auto ring = SurfaceSampler(world, options).Sample({room.center});
  ASSERT_FALSE(ring.empty());
  for (const Eigen::Vector3d& p : ring) {
    const double r = (p - room.center).norm();
    EXPECT_GT(r, 2.5);
    EXPECT_LE(r, 3.5 + 1e-9);
  }
}

TEST(SurfaceSampler, RejectsInvalidOptionsAndInputs) {
  const World world = test::BoxRoom().MakeWorld();
  SurfaceSamplerOptions bad;
  bad.directions_per_viewpoint = 0;
  EXPECT_THROW((SurfaceSampler{world, bad}), std::invalid_argument);
  bad = {};
  bad.voxel_m = 0.0;
  EXPECT_THROW((SurfaceSampler{world, bad}), std::invalid_argument);
  bad = {};
  bad.max_range_m = std::numeric_limits<double>::infinity();
  EXPECT_THROW((SurfaceSampler{world, bad}), std::invalid_argument);
  bad = {};
  bad.min_range_m = 40.0;
  EXPECT_THROW((SurfaceSampler{world, bad}), std::invalid_argument);
  World unbuilt;
  unbuilt.Add(std::make_unique<SpherePrimitive>(Eigen::Vector3d::Zero(), 1.0));
  EXPECT_THROW((SurfaceSampler{unbuilt, {}}), std::invalid_argument);
  EXPECT_THROW(SurfaceSampler(world, {}).Sample({Eigen::Vector3d(NAN, 0.0, 0.0)}), std::invalid_argument);
  EXPECT_TRUE(SurfaceSampler(world, {}).Sample({}).empty());
}

// A straight 4 m move along x (minimum jerk, 1 m/s peak), a 3 s dwell, then
// 1 m up: viewpoints every 0.5 m of travel plus the dwell point and the end.
TEST(TrajectoryViewpoints, EveryHalfMetreOfTravelAndAtDwells) {
  WaypointTrajectoryOptions options;
  options.max_speed_m_s = 1.0;
  options.max_acceleration_m_s2 = 1.0;
  options.static_start_s = 2.0;
  const WaypointTrajectory trajectory({{Eigen::Vector3d(0, 0, 1), 0.0, 0.0},
                                       {Eigen::Vector3d(4.1, 0, 1), 0.0, 3.0},
                                       {Eigen::Vector3d(4.1, 0, 2), 0.0, 0.0}},
                                      options);
  const auto viewpoints = TrajectoryViewpoints(trajectory, trajectory.end_time_s());
  ASSERT_GE(viewpoints.size(), 3u);
  EXPECT_EQ(viewpoints.front(), Eigen::Vector3d(0, 0, 1));
  EXPECT_LT((viewpoints.back() - Eigen::Vector3d(4.1, 0, 2)).norm(), 1e-9);
  // The dwell point (4.1, 0, 1) is a viewpoint (to within the 1 mm/s dwell threshold).
  double nearest_dwell = 1e9;
  for (const auto& v : viewpoints) nearest_dwell = std::min(nearest_dwell, (v - Eigen::Vector3d(4.1, 0, 1)).norm());
  EXPECT_LT(nearest_dwell, 1e-3);
  // Consecutive viewpoints are at most 0.5 m of travel plus one 0.05 s step apart.
  for (std::size_t i = 1; i < viewpoints.size(); ++i) {
    EXPECT_LE((viewpoints[i] - viewpoints[i - 1]).norm(), 0.5 + 0.05 * 1.0 + 1e-9) << i;
  }
  // 4.1 m + 1 m of travel: 10 spacing viewpoints, the start, the dwell and the end, give or take one.
  EXPECT_GE(viewpoints.size(), 12u);
  EXPECT_LE(viewpoints.size(), 14u);
  // Cut at the end of the static start: the body has not moved.
  const auto resting = TrajectoryViewpoints(trajectory, 1.5);
  ASSERT_EQ(resting.size(), 1u);
  EXPECT_THROW(TrajectoryViewpoints(trajectory, 10.0, {0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
