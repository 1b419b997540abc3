#include "map/LineGapFill.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A vertical line of beams from sensor (0, 0, 0) at azimuth psi hitting the
// wall x = 3: beam i at elevation (i - 10) * 3 deg.
std::vector<BeamReturn> WallLine(double psi_rad, float wall_x = 3.0f) {
  std::vector<BeamReturn> out;
  for (int i = 0; i <= 20; ++i) {
    const double elevation = (i - 10) * 3.0 * kPi / 180.0;
    const Eigen::Vector3d dir(std::cos(elevation) * std::cos(psi_rad), std::cos(elevation) * std::sin(psi_rad),
                              std::sin(elevation));
    const double range = wall_x / dir.x();
    out.push_back({static_cast<std::uint16_t>(i), (range * dir).cast<float>()});
  }
  return out;
}

TEST(LineGapFillTest, FillsTheWallBetweenConsecutiveLinesOnTheWall) {
  LineGapFill fill(LineGapFillOptions{});
  EXPECT_TRUE(fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(0.0)).empty());  // first line: nothing to pair
  const double step = 4.5 * kPi / 180.0;                                       // 30 rpm at 40 lines/s
  const std::vector<Eigen::Vector3f> filled = fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(step));
  // 21 beams, gaps of 0.24-0.25 m at 0.05 m steps: 4 points each.
  ASSERT_EQ(filled.size(), 21u * 4u);
  for (const Eigen::Vector3f& p : filled) {
    EXPECT_NEAR(p.x(), 3.0f, 1e-5f);  // on the wall
    EXPECT_GT(p.y(), 0.0f);           // between the two lines
    EXPECT_LT(p.y(), 3.0 * std::tan(step));
  }
}

TEST(LineGapFillTest, LeavesDepthJumpsHolesAndPausesOpen) {
  const double step = 4.5 * kPi / 180.0;
  {  // The next line hits a wall 0.5 m further back: the gap runs along the beams.
    LineGapFill fill(LineGapFillOptions{});
    fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(0.0, 1.0f));
    EXPECT_TRUE(fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(step, 1.5f)).empty());
    // The same wall on both lines is filled.
    fill.Add(0.05, Eigen::Vector3f::Zero(), WallLine(0.0, 1.0f));
    EXPECT_FALSE(fill.Add(0.075, Eigen::Vector3f::Zero(), WallLine(step, 1.0f)).empty());
  }
  {  // Gaps over max_gap_m (a wall 20 m away: 1.6 m between the lines) stay open.
    LineGapFill fill(LineGapFillOptions{});
    fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(0.0, 20.0f));
    EXPECT_TRUE(fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(step, 20.0f)).empty());
  }
  {  // Lines further apart in time than max_line_interval_s are not consecutive.
    LineGapFill fill(LineGapFillOptions{});
    fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(0.0));
    EXPECT_TRUE(fill.Add(0.5, Eigen::Vector3f::Zero(), WallLine(step)).empty());
    EXPECT_FALSE(fill.Add(0.525, Eigen::Vector3f::Zero(), WallLine(2.0 * step)).empty());  // paired again
  }
}

double Deg(double degrees) { return degrees * kPi / 180.0; }

// The wall x = 0.5 seen at azimuths 76-78 deg: the gaps between lines run
// along the wall, 76.5-77.5 deg from the beams' normal incidence.
TEST(LineGapFillTest, FillsAGrazingWallWhereTheBeamsGapsContinue) {
  LineGapFill fill(LineGapFillOptions{});
  fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(Deg(76.0), 0.5f));
  // Past max_incidence_deg (75) with no previous gap to continue: open.
  EXPECT_TRUE(fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(Deg(77.0), 0.5f)).empty());
  // The next gap of every beam continues the last one along the wall: filled.
  const std::vector<Eigen::Vector3f> filled = fill.Add(0.05, Eigen::Vector3f::Zero(), WallLine(Deg(78.0), 0.5f));
  ASSERT_GE(filled.size(), 21u * 3u);  // gaps of 0.19-0.22 m at 0.05 m steps: at least 3 points each
  for (const Eigen::Vector3f& p : filled) {
    EXPECT_NEAR(p.x(), 0.5f, 1e-5f);  // on the wall
    EXPECT_GT(p.y(), 0.5f * std::tan(Deg(77.0)) - 1e-4);
    EXPECT_LT(p.y(), 0.5f * std::tan(Deg(78.0)) * 1.1);
  }
}

TEST(LineGapFillTest, LeavesGrazingDepthJumpsAndGapsBeyondTheGrazingLimitOpen) {
  {  // Two lines on the grazing wall, the third on something 0.1 m nearer
     // (83 deg from normal incidence, within the grazing limit): the gap
     // turns back towards the sensor.
    LineGapFill fill(LineGapFillOptions{});
    fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(Deg(76.0), 0.5f));
    fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(Deg(77.0), 0.5f));
    EXPECT_TRUE(fill.Add(0.05, Eigen::Vector3f::Zero(), WallLine(Deg(78.0), 0.4f)).empty());
    // The same three lines on the wall: filled (above).
    LineGapFill same(LineGapFillOptions{});
    same.Add(0.0, Eigen::Vector3f::Zero(), WallLine(Deg(76.0), 0.5f));
    same.Add(0.025, Eigen::Vector3f::Zero(), WallLine(Deg(77.0), 0.5f));
    EXPECT_FALSE(same.Add(0.05, Eigen::Vector3f::Zero(), WallLine(Deg(78.0), 0.5f)).empty());
  }
  {  // The wall x = 0.05 at 86-88 deg: past max_grazing_incidence_deg (85), never filled.
    LineGapFill fill(LineGapFillOptions{});
    fill.Add(0.0, Eigen::Vector3f::Zero(), WallLine(Deg(86.0), 0.05f));
    fill.Add(0.025, Eigen::Vector3f::Zero(), WallLine(Deg(87.0), 0.05f));
    EXPECT_TRUE(fill.Add(0.05, Eigen::Vector3f::Zero(), WallLine(Deg(88.0), 0.05f)).empty());
  }
}

TEST(LineGapFillTest, PairsOnlyBeamsWithAReturnInBothLines) {
  const double step = 4.5 * kPi / 180.0;
  LineGapFill fill(LineGapFillOptions{});
  std::vector<BeamReturn> first = WallLine(0.0);
  first.erase(first.begin() + 5);  // beam 5 had no return
  fill.Add(0.0, Eigen::Vector3f::Zero(), first);
  std::vector<BeamReturn> second = WallLine(step);
  second.resize(10);  // beams 10-20 had none
  EXPECT_EQ(fill.Add(0.025, Eigen::Vector3f::Zero(), second).size(), 9u * 4u);
}

TEST(LineGapFillTest, LineReturnsNumbersBeamsByFiringTime) {
  LineScan line;
  line.start_time_s = 10.0;
  line.time_increment_s = 0.001;
  line.ranges_m.assign(4, 1.0f);
  BodyScan body;
  for (int beam : {0, 2, 3}) {  // beam 1 dropped by deskewing
    Point p;
    p.time_s = 10.0 + 0.001 * beam;
    body.points.push_back(p);
  }
  const std::vector<Eigen::Vector3f> points_map(3, Eigen::Vector3f::Ones());
  const std::vector<BeamReturn> returns = LineReturns(line, body, points_map);
  ASSERT_EQ(returns.size(), 3u);
  EXPECT_EQ(returns[0].beam, 0);
  EXPECT_EQ(returns[1].beam, 2);
  EXPECT_EQ(returns[2].beam, 3);
  line.time_increment_s = 0.0;  // beams not timed: no returns to pair
  EXPECT_TRUE(LineReturns(line, body, points_map).empty());
}

TEST(LineGapFillTest, RejectsInvalidOptions) {
  std::string why;
  EXPECT_TRUE(LineGapFillOptions{}.IsValid(&why));
  LineGapFillOptions o;
  o.step_m = 0.0;
  EXPECT_FALSE(o.IsValid(&why));
  o = LineGapFillOptions{};
  o.max_gap_m = 0.01;
  EXPECT_FALSE(o.IsValid(&why));
  o = LineGapFillOptions{};
  o.max_incidence_deg = 90.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("max_incidence_deg"), std::string::npos);
  o = LineGapFillOptions{};
  o.max_grazing_incidence_deg = 70.0;  // below max_incidence_deg
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("max_grazing_incidence_deg"), std::string::npos);
  o = LineGapFillOptions{};
  o.max_turn_deg = 90.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("max_turn_deg"), std::string::npos);
  o = LineGapFillOptions{};
  o.max_line_interval_s = -1.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_THROW(LineGapFill{o}, std::invalid_argument);
}

}  // namespace
}  // namespace unimap::map
