// The motor payloads (rotating_3d, rotating_2d): encoder angle to motor angle
// to T_body_lidar, and the default mounting geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "PluginTestSupport.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

using plugin_test::kDeg;
using plugin_test::kPi;

class MotorModelTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { loaded_ = plugin_test::LoadPayload(GetParam()); }
  PayloadPlugin& plugin() { return *loaded_.plugin; }

  LoadedPlugin loaded_;
};

TEST_P(MotorModelTest, MotorAngleAppliesEncoderOffsetAndDirection) {
  // The encoder reads 5.5 rad at t = 20 s and turns at 2 rad/s, wrapping into
  // [0, 2pi) several times over the 3 s track.
  const EncoderTrack encoder = plugin_test::ConstantRateEncoder(20.0, 23.0, 5.5, 2.0, 37.0);
  const struct {
    double offset_deg;
    int direction;
  } cases[] = {{30.0, -1}, {-45.0, 1}, {0.0, 1}};
  for (const auto& c : cases) {
    plugin_test::ConfigureWith(&plugin(), {{"motor.encoder_offset_deg", c.offset_deg},
                                           {"motor.encoder_direction", std::int64_t{c.direction}}});
    for (const double t : {20.0, 20.013, 21.5, 22.7777, 23.0}) {
      // theta = direction * encoder(t) + offset, encoder unwrapped.
      const double expected = c.direction * (5.5 + 2.0 * (t - 20.0)) + c.offset_deg * kDeg;
      EXPECT_NEAR(plugin().MotorAngleAt(encoder, t), expected, 1e-9)
          << "offset " << c.offset_deg << " direction " << c.direction << " t " << t;
    }
  }
}

TEST_P(MotorModelTest, BodyFromLidarFollowsTheMountAtTheEncoderAngle) {
  const plugin_test::MountTruth mount;
  plugin_test::ConfigureWith(&plugin(), mount.Overrides());
  const EncoderTrack encoder = plugin_test::ConstantRateEncoder(0.0, 2.0, 0.3, kPi, 100.0);
  for (const double t : {0.0, 0.123, 0.5, 1.0, 1.987}) {
    const Eigen::Isometry3d expected = mount.BodyFromLidar(mount.MotorAngle(0.3 + kPi * t));
    EXPECT_TRUE(plugin().BodyFromLidarAt(encoder, t).isApprox(expected, 1e-12)) << "t " << t;
  }
}

TEST_P(MotorModelTest, DefaultScanPlaneContainsTheVerticalMotorAxis) {
  // Defaults: motor about body z, LiDAR rolled 90 deg; the scan plane (LiDAR
  // x-y) is vertical, contains the motor axis and faces theta:
  //   x_lidar = (cos theta, sin theta, 0), y_lidar = +z_body.
  const EncoderTrack encoder = plugin_test::ConstantRateEncoder(0.0, 2.0, 0.0, kPi, 100.0);
  const auto& defaults = plugin().Defaults();
  ASSERT_NE(defaults.Find("motor.rate_rpm"), nullptr);
  EXPECT_EQ(std::get<double>(defaults.Find("motor.rate_rpm")->default_value), 30.0);
  for (int k = 0; k < 12; ++k) {
    const double t = 2.0 * static_cast<double>(k) / 12.0;
    const double theta = kPi * t;
    const Eigen::Matrix3d R = plugin().BodyFromLidarAt(encoder, t).linear();
    EXPECT_LT((R.col(0) - Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0)).norm(), 1e-12) << "theta " << theta;
    EXPECT_LT((R.col(1) - Eigen::Vector3d::UnitZ()).norm(), 1e-12) << "theta " << theta;
  }
}

INSTANTIATE_TEST_SUITE_P(MotorPayloads, MotorModelTest, ::testing::Values("rotating_3d", "rotating_2d"),
                         plugin_test::PayloadTestName);

}  // namespace
}  // namespace unimap
