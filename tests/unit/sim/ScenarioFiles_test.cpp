// Facts about the shipped scenarios (configs/scenarios/*.yaml), computed from
// their worlds and trajectories without simulating them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "BoxPrimitive.hpp"
#include "CylinderPrimitive.hpp"
#include "HeightfieldPrimitive.hpp"
#include "Scenario.hpp"
#include "SpherePrimitive.hpp"
#include "WorldLoader.hpp"

namespace unimap::sim {
namespace {

std::filesystem::path ScenarioFile(const std::string& name) {
  return std::filesystem::path(UNIMAP_SOURCE_DIR) / "configs" / "scenarios" / (name + ".yaml");
}

// True when p is inside the solid of a closed primitive (box, cylinder,
// sphere) or below a heightfield; planes have no inside.
bool Inside(const Primitive& primitive, const Eigen::Vector3d& p) {
  if (const auto* box = dynamic_cast<const BoxPrimitive*>(&primitive)) {
    const Eigen::Vector3d q = box->rotation().transpose() * (p - box->center());
    return (q.cwiseAbs().array() < 0.5 * box->size().array()).all();
  }
  if (const auto* cylinder = dynamic_cast<const CylinderPrimitive*>(&primitive)) {
    const Eigen::Vector3d axis = cylinder->axis().normalized();
    const double along = (p - cylinder->base()).dot(axis);
    const double radial = ((p - cylinder->base()) - along * axis).norm();
    return along > 0.0 && along < cylinder->height() && radial < cylinder->radius();
  }
  if (const auto* sphere = dynamic_cast<const SpherePrimitive*>(&primitive)) {
    return (p - sphere->center()).norm() < sphere->radius();
  }
  if (const auto* ground = dynamic_cast<const HeightfieldPrimitive*>(&primitive)) {
    const Eigen::AlignedBox3d b = ground->Bounds();
    return p.x() >= b.min().x() && p.x() <= b.max().x() && p.y() >= b.min().y() && p.y() <= b.max().y() &&
           p.z() < ground->Height(p.x(), p.y());
  }
  return false;
}

class ScenarioFileTest : public ::testing::TestWithParam<std::string> {};

// The body keeps more than 0.3 m from every surface at samples 5 cm of
// travel apart at most (<= 1.2 m/s x 0.04 s); the surface distance is
// 1-Lipschitz, so the path never crosses a surface between samples either.
// It starts in free space: every solid holding the start holds the whole
// path (it is an enclosure, like the tunnel's box), so the path is in free space.
TEST_P(ScenarioFileTest, LoadsAndItsTrajectoryStaysInFreeSpace) {
  const Scenario s = LoadScenario(ScenarioFile(GetParam()));
  EXPECT_EQ(s.name, GetParam());
  EXPECT_TRUE(std::filesystem::exists(s.payload)) << s.payload;
  const World world = LoadWorld(s.world, s.world_file);
  const WaypointTrajectory traj = s.MakeTrajectory();
  std::vector<Eigen::Vector3d> samples;
  for (double t = 0.0; t <= traj.end_time_s(); t += 0.04) samples.push_back(traj.At(t).position_m);
  samples.push_back(traj.At(traj.end_time_s()).position_m);
  double closest = 1e9;
  for (const Eigen::Vector3d& p : samples) closest = std::min(closest, world.SurfaceDistance(p));
  EXPECT_GT(closest, 0.3);
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (!Inside(world.primitive(i), samples.front())) continue;
    for (const Eigen::Vector3d& p : samples) {
      ASSERT_TRUE(Inside(world.primitive(i), p)) << "primitive " << i << " holds the start but not " << p.transpose();
    }
  }
  EXPECT_LE(traj.MaxSpeed(traj.end_time_s()), s.trajectory.max_speed_m_s * (1 + 1e-12));
  EXPECT_GE(traj.options().static_start_s, 2.0);  // time for gravity alignment and gyro bias
}

INSTANTIATE_TEST_SUITE_P(Shipped, ScenarioFileTest,
                         ::testing::Values("tunnel", "corridor_loop", "patio", "narrow_hallway"));

// Boxes of a world with the given edge lengths.
int CountBoxes(const World& world, const Eigen::Vector3d& size) {
  int n = 0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const auto* box = dynamic_cast<const BoxPrimitive*>(&world.primitive(i));
    if (box != nullptr && (box->size() - size).norm() < 1e-9) ++n;
  }
  return n;
}

// The paper's tunnel: 108 m x 5.8 m x 7 m, 8 train cars (11 m x 3 m x 3 m
// bodies), ~165 m travelled in ~15 min at <= 1.13 m/s.
TEST(ScenarioFiles, TunnelMatchesThePaper) {
  const Scenario s = LoadScenario(ScenarioFile("tunnel"));
  EXPECT_EQ(s.payload, (std::filesystem::path(UNIMAP_SOURCE_DIR) / "configs/platforms/rotating_hokuyo.yaml")
                           .lexically_normal()
                           .string());
  const World world = LoadWorld(s.world, s.world_file);
  EXPECT_EQ(CountBoxes(world, Eigen::Vector3d(108, 5.8, 7)), 1);
  EXPECT_EQ(CountBoxes(world, Eigen::Vector3d(11, 3, 3)), 8);
  EXPECT_TRUE(world.Bounds().sizes().isApprox(Eigen::Vector3d(108, 5.8, 7)));
  const WaypointTrajectory traj = s.MakeTrajectory();
  const double end = traj.end_time_s();
  EXPECT_NEAR(traj.PathLength(end), 165.0, 16.5);
  EXPECT_LE(traj.MaxSpeed(end), 1.13 + 1e-12);
  EXPECT_GT(traj.MaxSpeed(end), 1.12);
  EXPECT_NEAR(end / 60.0, 15.0, 1.0);
  // Along the tunnel: from one end to beyond the last car.
  EXPECT_LT(traj.At(0.0).position_m.x(), 4.75);
  double max_x = 0.0;
  for (double t = 0.0; t < end; t += 1.0) max_x = std::max(max_x, traj.At(t).position_m.x());
  EXPECT_GT(max_x, 103.25);
}

// Horizontal free width across the direction of travel, by ray casts.
double WidthAcross(const World& world, const KinematicState& state) {
  const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(state.velocity_m_s).normalized();
  const auto left = world.Cast(Ray{state.position_m, across}, 0.0, 100.0);
  const auto right = world.Cast(Ray{state.position_m, -across}, 0.0, 100.0);
  return left && right ? left->range_m + right->range_m : 1e9;
}

TEST(ScenarioFiles, NarrowHallwayIs1point1MetersWideAtItsNarrowest) {
  const Scenario s = LoadScenario(ScenarioFile("narrow_hallway"));
  const World world = LoadWorld(s.world, s.world_file);
  const WaypointTrajectory traj = s.MakeTrajectory();
  double narrowest = 1e9;
  for (double t = 0.0; t < traj.end_time_s(); t += 0.1) {
    const KinematicState state = traj.At(t);
    if (state.velocity_m_s.norm() > 0.05) narrowest = std::min(narrowest, WidthAcross(world, state));
  }
  EXPECT_NEAR(narrowest, 1.1, 1e-9);
  EXPECT_LE(traj.MaxSpeed(traj.end_time_s()), 0.6 + 1e-12);
  // A loop: back to the start.
  EXPECT_LT((traj.At(traj.end_time_s()).position_m - traj.At(0.0).position_m).norm(), 1e-12);
}

TEST(ScenarioFiles, CorridorLoopIsA40By20LoopTwoMetersWide) {
  const Scenario s = LoadScenario(ScenarioFile("corridor_loop"));
  const World world = LoadWorld(s.world, s.world_file);
  const WaypointTrajectory traj = s.MakeTrajectory();
  std::vector<double> widths;
  Eigen::AlignedBox3d path_box;
  for (double t = 0.0; t < traj.end_time_s(); t += 0.1) {
    const KinematicState state = traj.At(t);
    path_box.extend(state.position_m);
    if (state.velocity_m_s.norm() > 0.05) widths.push_back(WidthAcross(world, state));
  }
  std::sort(widths.begin(), widths.end());
  EXPECT_NEAR(widths[widths.size() / 2], 2.0, 1e-9);  // median: plain corridor
  EXPECT_GE(widths.front(), 1.95);                    // doors stand 4 cm proud
  EXPECT_GE(widths.back(), 2.9);                      // alcoves add 1 m
  EXPECT_NEAR(path_box.sizes().x(), 38.0, 1e-9);      // centre line of a 40 m x 20 m loop
  EXPECT_NEAR(path_box.sizes().y(), 18.0, 1e-9);
  EXPECT_LE(traj.MaxSpeed(traj.end_time_s()), 1.2 + 1e-12);
  EXPECT_LT((traj.At(traj.end_time_s()).position_m - traj.At(0.0).position_m).norm(), 1e-12);
}

TEST(ScenarioFiles, PatioIsAnOutdoorCourtyardWithTreesAndUnevenGround) {
  const Scenario s = LoadScenario(ScenarioFile("patio"));
  const World world = LoadWorld(s.world, s.world_file);
  int heightfields = 0, spheres = 0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    heightfields += world.primitive(i).Kind() == "heightfield";
    spheres += world.primitive(i).Kind() == "sphere";
  }
  EXPECT_EQ(heightfields, 1);
  EXPECT_GE(spheres, 6);  // tree crowns
  // Open sky: a ray straight up from the middle of the courtyard hits nothing.
  EXPECT_FALSE(world.Cast(Ray{Eigen::Vector3d(10, -10, 3), Eigen::Vector3d::UnitZ()}, 0.0, 1000.0).has_value());
  // The courtyard between the building faces is 40 m x 40 m (rays along x and y at 3 m).
  const Eigen::Vector3d mid(4, 4, 3);
  const auto east = world.Cast(Ray{mid, Eigen::Vector3d::UnitX()}, 0.0, 100.0);
  const auto west = world.Cast(Ray{mid, -Eigen::Vector3d::UnitX()}, 0.0, 100.0);
  ASSERT_TRUE(east && west);
  EXPECT_NEAR(east->range_m + west->range_m, 40.0, 1e-9);
  const WaypointTrajectory traj = s.MakeTrajectory();
  EXPECT_NEAR(traj.PathLength(traj.end_time_s()), 100.0, 0.1);  // mid-side waypoints 0.2 m higher or lower
}

}  // namespace
}  // namespace unimap::sim
