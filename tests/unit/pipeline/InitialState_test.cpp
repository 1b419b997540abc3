#include "pipeline/InitialState.hpp"

#include <random>

#include <gtest/gtest.h>

#include "estimation/So3.hpp"

namespace unimap::pipeline {
namespace {

constexpr double kGravity = 9.80665;

// count samples at 200 Hz of a body at rest with attitude q and gyro bias
// bg; noise (m/s^2, a tenth of it in rad/s) shakes it.
std::vector<ImuSample> Window(const Eigen::Quaterniond& q, const Eigen::Vector3d& bg, double noise, int count) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<ImuSample> out;
  for (int i = 0; i < count; ++i) {
    ImuSample s;
    s.time_s = 2.0 + 0.005 * i;
    s.accel_m_s2 = q.conjugate() * Eigen::Vector3d(0, 0, kGravity) + noise * Eigen::Vector3d(n(rng), n(rng), n(rng));
    s.gyro_rad_s = bg + 0.1 * noise * Eigen::Vector3d(n(rng), n(rng), n(rng));
    out.push_back(s);
  }
  return out;
}

LocalizerOptions Options() {
  LocalizerOptions options;
  options.eskf.gravity_m_s2 = kGravity;
  return options;
}

TEST(InitialStateFromWindow, StaticWindowGivesTiltAndGyroBiasAtTheLastSample) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()));
  const Eigen::Vector3d bg(0.002, -0.001, 0.003);
  const std::vector<ImuSample> window = Window(q, bg, 0.0, 200);
  const InitialState start = InitialStateFromWindow(window, std::nullopt, Options());
  EXPECT_TRUE(start.notes.empty());
  EXPECT_FALSE(start.attitude.has_value());
  EXPECT_DOUBLE_EQ(start.state.time_s, window.back().time_s);
  EXPECT_LT(estimation::LogQ(start.state.q_world_body.conjugate() * q).norm(), 1e-9);
  EXPECT_TRUE(start.state.gyro_bias_rad_s.isApprox(bg, 1e-12));
  EXPECT_TRUE(start.state.p_world_body_m.isZero());
  EXPECT_TRUE(start.state.v_world_m_s.isZero());
}

TEST(InitialStateFromWindow, ShakenWindowStartsLevelAndSaysWhy) {
  const InitialState start = InitialStateFromWindow(
      Window(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 2.0, 200), std::nullopt, Options());
  ASSERT_EQ(start.notes.size(), 1u);
  EXPECT_EQ(start.notes[0].rfind("initial alignment: ", 0), 0u) << start.notes[0];
  EXPECT_NE(start.notes[0].find("starting level"), std::string::npos) << start.notes[0];
  EXPECT_TRUE(start.state.q_world_body.isApprox(Eigen::Quaterniond::Identity()));
  EXPECT_TRUE(start.state.gyro_bias_rad_s.isZero());
}

TEST(InitialStateFromWindow, GivenPosePlacesTheStateThere) {
  Eigen::Isometry3d T_map_body = Eigen::Isometry3d::Identity();
  T_map_body.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T_map_body.translation() = Eigen::Vector3d(3.0, -1.0, 0.5);
  LocalizerOptions options = Options();
  options.initial_attitude = estimation::InitialAttitude::kGravity;
  const InitialState start = InitialStateFromWindow(
      Window(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 0.0, 200), T_map_body, options);
  EXPECT_TRUE(start.notes.empty());
  ASSERT_TRUE(start.attitude.has_value());
  EXPECT_EQ(*start.attitude, estimation::InitialAttitude::kGravity);
  EXPECT_TRUE(start.state.p_world_body_m.isApprox(T_map_body.translation()));
  EXPECT_LT(estimation::LogQ(start.state.q_world_body.conjugate() * Eigen::Quaterniond(T_map_body.linear())).norm(),
            1e-9);
}

}  // namespace
}  // namespace unimap::pipeline
