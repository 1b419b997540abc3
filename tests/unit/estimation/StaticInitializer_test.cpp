#include "estimation/StaticInitializer.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "estimation/So3.hpp"

namespace unimap::estimation {
namespace {

std::vector<ImuSample> StaticSamples(const Eigen::Quaterniond& q, const Eigen::Vector3d& bg, double noise, int count,
                                     const Eigen::Vector3d& ba = Eigen::Vector3d::Zero()) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, noise);
  std::vector<ImuSample> out;
  for (int i = 0; i < count; ++i) {
    ImuSample s;
    s.time_s = 0.005 * i;
    s.accel_m_s2 = q.conjugate() * Eigen::Vector3d(0, 0, 9.81) + ba + Eigen::Vector3d(n(rng), n(rng), n(rng));
    s.gyro_rad_s = bg + Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.1;
    out.push_back(s);
  }
  return out;
}

TEST(AlignFromStatic, RecoversRollPitchAndGyroBias) {
  const Eigen::Quaterniond q = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.15, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d bg(0.01, -0.02, 0.005);
  StaticAlignmentOptions options;
  options.yaw_rad = 0.3;
  const StaticAlignment a = AlignFromStatic(StaticSamples(q, bg, 0.0, 400), options);
  ASSERT_TRUE(a.ok) << a.reason;
  EXPECT_LT(LogQ(a.q_world_body.conjugate() * q).norm(), 1e-12);
  EXPECT_TRUE(a.gyro_bias_rad_s.isApprox(bg, 1e-12));
  EXPECT_NEAR(a.gravity_m_s2, 9.81, 1e-12);
}

TEST(AlignFromStatic, GyroBiasComesWithItsStandardError) {
  const Eigen::Vector3d bg(0.004, -0.003, 0.002);
  // Gyroscope white noise 0.002 rad/s per sample (StaticSamples: a tenth
  // of the accelerometer's), 400 samples: the mean's error is 0.002 / 20.
  const StaticAlignment a = AlignFromStatic(StaticSamples(Eigen::Quaterniond::Identity(), bg, 0.02, 400), {});
  ASSERT_TRUE(a.ok) << a.reason;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.gyro_bias_std_rad_s[i], 1e-4, 1e-5) << i;
    EXPECT_LT(std::abs(a.gyro_bias_rad_s[i] - bg[i]), 4.0 * a.gyro_bias_std_rad_s[i]) << i;
  }
}

TEST(AlignFromStatic, RefusesMotionAndShortWindows) {
  StaticAlignmentOptions options;
  EXPECT_FALSE(
      AlignFromStatic(StaticSamples(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 0.0, 50), options).ok);
  const StaticAlignment moving =
      AlignFromStatic(StaticSamples(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 1.0, 400), options);
  EXPECT_FALSE(moving.ok);
  EXPECT_NE(moving.reason.find("not static"), std::string::npos);
}

Eigen::Isometry3d Pose(const Eigen::Quaterniond& q, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = p;
  return T;
}

// A tilted body at rest with an accelerometer bias: the bias is
// indistinguishable from tilt for gravity alignment.
struct BiasedStart {
  Eigen::Quaterniond q = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(-0.03, Eigen::Vector3d::UnitX());
  Eigen::Vector3d ba{0.05, -0.04, 0.03};
  Eigen::Vector3d p{2.0, -1.0, 1.5};
  StaticAlignment alignment = AlignFromStatic(StaticSamples(q, Eigen::Vector3d::Zero(), 0.0, 400, ba), {});
};

TEST(PlaceAtPose, PoseAttitudeRecoversTheAccelerometerBias) {
  const BiasedStart start;
  ASSERT_TRUE(start.alignment.ok);
  // Gravity alignment alone is off by the bias over g (about 0.3 deg here).
  EXPECT_GT(LogQ(start.alignment.q_world_body.conjugate() * start.q).tail<2>().norm(), 0.004);
  NavState state;
  const PoseStart placed =
      PlaceAtPose(start.alignment, Pose(start.q, start.p), InitialAttitude::kPose, 9.81, 0.3, &state);
  EXPECT_EQ(placed.attitude, InitialAttitude::kPose);
  EXPECT_FALSE(placed.fell_back);
  EXPECT_TRUE(placed.note.empty()) << placed.note;
  EXPECT_TRUE(state.p_world_body_m.isApprox(start.p, 1e-12));
  EXPECT_LT(LogQ(state.q_world_body.conjugate() * start.q).norm(), 1e-12);
  EXPECT_LT((state.accel_bias_m_s2 - start.ba).norm(), 1e-9);
}

TEST(PlaceAtPose, GravityAttitudeKeepsHeadingOfThePoseAndTiltOfGravity) {
  const BiasedStart start;
  NavState state;
  const PoseStart placed =
      PlaceAtPose(start.alignment, Pose(start.q, start.p), InitialAttitude::kGravity, 9.81, 0.3, &state);
  EXPECT_EQ(placed.attitude, InitialAttitude::kGravity);
  EXPECT_FALSE(placed.fell_back);
  EXPECT_TRUE(state.accel_bias_m_s2.isZero());
  // Up as gravity says (the biased specific force), heading as the pose says.
  const Eigen::Vector3d up_body = state.q_world_body.conjugate() * Eigen::Vector3d::UnitZ();
  EXPECT_LT((up_body - start.alignment.mean_specific_force_m_s2.normalized()).norm(), 1e-12);
  const Eigen::Vector3d x_state = state.q_world_body * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d x_pose = start.q * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(x_state.y(), x_state.x()), std::atan2(x_pose.y(), x_pose.x()), 1e-12);
}

TEST(PlaceAtPose, AWrongTiltFallsBackToGravityWithANote) {
  const BiasedStart start;
  // The given pose is level although the body is tilted by 2 deg: implied bias 0.34 m/s^2.
  const Eigen::Quaterniond level(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond tilted = level * Eigen::AngleAxisd(0.035, Eigen::Vector3d::UnitX());
  const StaticAlignment alignment = AlignFromStatic(StaticSamples(tilted, Eigen::Vector3d::Zero(), 0.0, 400), {});
  NavState state;
  const PoseStart placed = PlaceAtPose(alignment, Pose(level, start.p), InitialAttitude::kPose, 9.81, 0.3, &state);
  EXPECT_EQ(placed.attitude, InitialAttitude::kGravity);
  EXPECT_TRUE(placed.fell_back);
  EXPECT_NE(placed.note.find("disagrees with gravity"), std::string::npos) << placed.note;
  EXPECT_TRUE(state.accel_bias_m_s2.isZero());
  EXPECT_LT(LogQ(state.q_world_body.conjugate() * tilted).norm(), 1e-9);
}

TEST(PlaceAtPose, WithoutAlignmentTakesThePoseAsIs) {
  const BiasedStart start;
  StaticAlignment failed;
  failed.reason = "too few samples";
  NavState state;
  const PoseStart placed = PlaceAtPose(failed, Pose(start.q, start.p), InitialAttitude::kGravity, 9.81, 0.3, &state);
  EXPECT_EQ(placed.attitude, InitialAttitude::kPose);
  EXPECT_LT(LogQ(state.q_world_body.conjugate() * start.q).norm(), 1e-12);
  EXPECT_TRUE(state.p_world_body_m.isApprox(start.p, 1e-12));
  EXPECT_TRUE(state.accel_bias_m_s2.isZero());
}

}  // namespace
}  // namespace unimap::estimation
