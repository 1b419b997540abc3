#include "estimation/StaticInitializer.hpp"

#include <random>

#include <gtest/gtest.h>

#include "estimation/So3.hpp"

namespace unimap::estimation {
namespace {

std::vector<ImuSample> StaticSamples(const Eigen::Quaterniond& q, const Eigen::Vector3d& bg,
                                     double noise, int count) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, noise);
  std::vector<ImuSample> out;
  for (int i = 0; i < count; ++i) {
    ImuSample s;
    s.time_s = 0.005 * i;
    s.accel_m_s2 = q.conjugate() * Eigen::Vector3d(0, 0, 9.81) + Eigen::Vector3d(n(rng), n(rng), n(rng));
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

TEST(AlignFromStatic, RefusesMotionAndShortWindows) {
  StaticAlignmentOptions options;
  EXPECT_FALSE(AlignFromStatic(StaticSamples(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 0.0, 50), options).ok);
  const StaticAlignment moving =
      AlignFromStatic(StaticSamples(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 1.0, 400), options);
  EXPECT_FALSE(moving.ok);
  EXPECT_NE(moving.reason.find("not static"), std::string::npos);
}

}  // namespace
}  // namespace unimap::estimation
