#include "unimap/MotorMotion.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

constexpr double kDeg = M_PI / 180.0;

MotorMotion Nodding(MotorMotion::Profile profile) {
  MotorMotion m;
  m.kind = MotorMotion::Kind::kOscillating;
  m.min_deg = -30.0;
  m.max_deg = 50.0;
  m.period_s = 4.0;
  m.profile = profile;
  return m;
}

TEST(MotorMotion, ConstantRateTurnsAtRpm) {
  MotorMotion m;
  m.rate_rpm = 30.0;  // half a turn per second
  EXPECT_DOUBLE_EQ(m.EncoderAngleRad(0.0), 0.0);
  EXPECT_NEAR(m.EncoderAngleRad(3.0), 3.0 * M_PI, 1e-12);
  EXPECT_TRUE(m.Wraps());
}

TEST(MotorMotion, SineNodStartsAtMinAndPeaksAtHalfPeriod) {
  const MotorMotion m = Nodding(MotorMotion::Profile::kSine);
  EXPECT_FALSE(m.Wraps());
  EXPECT_NEAR(m.EncoderAngleRad(0.0), -30.0 * kDeg, 1e-12);
  EXPECT_NEAR(m.EncoderAngleRad(1.0), 10.0 * kDeg, 1e-12);  // a quarter period: the middle
  EXPECT_NEAR(m.EncoderAngleRad(2.0), 50.0 * kDeg, 1e-12);
  EXPECT_NEAR(m.EncoderAngleRad(4.0), -30.0 * kDeg, 1e-12);
  EXPECT_NEAR(m.EncoderAngleRad(9.0), 10.0 * kDeg, 1e-12);  // periodic
  // mid - half_range cos(2 pi t / T) at any time.
  for (double t = 0.0; t < 12.0; t += 0.37) {
    EXPECT_NEAR(m.EncoderAngleRad(t), (10.0 - 40.0 * std::cos(2.0 * M_PI * t / 4.0)) * kDeg, 1e-12) << t;
  }
}

TEST(MotorMotion, TriangleNodMovesAtConstantSpeed) {
  const MotorMotion m = Nodding(MotorMotion::Profile::kTriangle);
  const double speed = 80.0 * kDeg / 2.0;  // 80 deg up in half a period
  EXPECT_NEAR(m.EncoderAngleRad(0.5), -30.0 * kDeg + 0.5 * speed, 1e-12);
  EXPECT_NEAR(m.EncoderAngleRad(2.0), 50.0 * kDeg, 1e-12);
  EXPECT_NEAR(m.EncoderAngleRad(3.0), 50.0 * kDeg - speed, 1e-12);  // on the way down
}

TEST(MotorMotion, StepperDwellsThenStepsToMaxAndBack) {
  MotorMotion m;
  m.kind = MotorMotion::Kind::kStepping;
  m.min_deg = 0.0;
  m.max_deg = 1.0;
  m.step_deg = 0.3;  // 4 steps up: 0.3, 0.6, 0.9, then 1.0 (the last one stops at max)
  m.step_s = 0.1;
  m.dwell_s = 0.4;
  EXPECT_FALSE(m.Wraps());
  EXPECT_NEAR(m.EncoderAngleRad(0.2), 0.0, 1e-12);           // dwelling at min
  EXPECT_NEAR(m.EncoderAngleRad(0.45), 0.15 * kDeg, 1e-12);  // half-way through the first step
  EXPECT_NEAR(m.EncoderAngleRad(0.7), 0.3 * kDeg, 1e-12);    // dwelling after it
  EXPECT_NEAR(m.EncoderAngleRad(1.9), 0.9 * kDeg, 1e-12);    // the last step's dwell
  EXPECT_NEAR(m.EncoderAngleRad(2.0), 1.0 * kDeg, 1e-12);    // at max (4 x 0.5 s)
  EXPECT_NEAR(m.EncoderAngleRad(2.2), 1.0 * kDeg, 1e-12);    // dwelling at max
  EXPECT_NEAR(m.EncoderAngleRad(2.7), 0.7 * kDeg, 1e-12);    // one step down
  EXPECT_NEAR(m.EncoderAngleRad(4.2), 0.0, 1e-12);           // back at min, next cycle
  // Never outside [min, max], and never faster than one step per step_s.
  double previous = m.EncoderAngleRad(0.0);
  for (double t = 0.001; t < 10.0; t += 0.001) {
    const double a = m.EncoderAngleRad(t);
    ASSERT_GE(a, -1e-12);
    ASSERT_LE(a, 1.0 * kDeg + 1e-12);
    ASSERT_LE(std::abs(a - previous), 0.3 * kDeg * 0.001 / 0.1 + 1e-9) << t;
    previous = a;
  }
}

TEST(MotorMotion, ReadsItsKeysAndNamesTheBadOne) {
  ParameterSet set;
  Nodding(MotorMotion::Profile::kTriangle).AddTo(&set);
  const MotorMotion read = MotorMotion::FromMap(set.DefaultMap());
  EXPECT_EQ(read.kind, MotorMotion::Kind::kOscillating);
  EXPECT_EQ(read.profile, MotorMotion::Profile::kTriangle);
  EXPECT_DOUBLE_EQ(read.min_deg, -30.0);
  EXPECT_DOUBLE_EQ(read.max_deg, 50.0);
  EXPECT_DOUBLE_EQ(read.period_s, 4.0);

  ParameterMap reversed = set.DefaultMap();
  reversed.Set("motor.max_deg", ParameterValue(-40.0));
  try {
    MotorMotion::FromMap(reversed);
    FAIL() << "a range with max below min was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "motor.max_deg");
  }
}

TEST(MotorMotion, OlderPayloadsWithOnlyARateAreConstant) {
  ParameterMap map;
  map.Set("motor.rate_rpm", ParameterValue(60.0));
  const MotorMotion m = MotorMotion::FromMap(map);
  EXPECT_EQ(m.kind, MotorMotion::Kind::kConstant);
  EXPECT_NEAR(m.EncoderAngleRad(1.0), 2.0 * M_PI, 1e-12);
  try {
    MotorMotion::FromMap(ParameterMap());
    FAIL() << "a payload stating no motion was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "motor.motion");
  }
}

}  // namespace
}  // namespace unimap
