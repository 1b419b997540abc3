#include "unimap/MotorMount.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

TEST(Extrinsic, RollPitchYawFollowsZYXConvention) {
  Extrinsic e;
  e.translation_m = Eigen::Vector3d(1, 2, 3);
  e.rpy_deg = Eigen::Vector3d(0, 0, 90);
  const Eigen::Isometry3d T = e.ToIsometry();
  EXPECT_TRUE((T * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(1, 3, 3), 1e-12));
  e.rpy_deg = Eigen::Vector3d(90, 0, 0);  // roll: y -> z
  EXPECT_TRUE((e.ToIsometry().linear() * Eigen::Vector3d(0, 1, 0)).isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  e.rpy_deg = Eigen::Vector3d(0, 90, 0);  // pitch: z -> x
  EXPECT_TRUE((e.ToIsometry().linear() * Eigen::Vector3d(0, 0, 1)).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
}

TEST(MotorMount, BodyFromLidarComposesExtrinsicsAndMotorRotation) {
  MotorMount m;
  m.body_motor.translation_m = Eigen::Vector3d(0, 0, 0.1);
  m.motor_lidar.translation_m = Eigen::Vector3d(0.05, 0, 0);
  m.axis_motor = Eigen::Vector3d(0, 0, 2.0);  // normalised on use
  // A point 1 m ahead of the LiDAR, motor at 90 deg about z: lands at +y.
  const Eigen::Vector3d p = m.BodyFromLidar(M_PI / 2) * Eigen::Vector3d(1, 0, 0);
  EXPECT_TRUE(p.isApprox(Eigen::Vector3d(0, 1.05, 0.1), 1e-12)) << p.transpose();
}

TEST(MotorMount, EncoderOffsetAndDirection) {
  MotorMount m;
  m.encoder_offset_deg = 90.0;
  m.encoder_direction = -1;
  EXPECT_NEAR(m.MotorAngle(0.25), -0.25 + M_PI / 2, 1e-15);
}

TEST(MotorMount, ParametersRoundTripAndAreChecked) {
  MotorMount m;
  m.axis_motor = Eigen::Vector3d(1, 0, 0);
  m.encoder_direction = -1;
  m.motor_lidar.rpy_deg = Eigen::Vector3d(0, 90, 0);
  ParameterSet set;
  m.AddTo(&set);
  std::string why;
  ASSERT_TRUE(set.IsValid(&why)) << why;
  ParameterMap map = set.DefaultMap();
  const MotorMount back = MotorMount::FromMap(map);
  EXPECT_EQ(back.axis_motor, m.axis_motor);
  EXPECT_EQ(back.encoder_direction, -1);
  EXPECT_TRUE(back.BodyFromLidar(0.3).isApprox(m.BodyFromLidar(0.3), 1e-15));
  map.Set("motor.axis", std::vector<double>{0, 0, 0});
  EXPECT_THROW(MotorMount::FromMap(map), ConfigError);
  map = set.DefaultMap();
  map.Set("motor.encoder_direction", std::int64_t{0});
  EXPECT_THROW(MotorMount::FromMap(map), ConfigError);
}

}  // namespace
}  // namespace unimap
