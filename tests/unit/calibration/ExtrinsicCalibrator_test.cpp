#include "calibration/ExtrinsicCalibrator.hpp"

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace unimap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;

// T_motor_lidar from [tx, ty, tz (m), roll, pitch, yaw (deg)], R = Rz Ry Rx
// (the platform files' convention).
Eigen::Isometry3d MotorLidar(const Vector6d& x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = x.head<3>();
  T.linear() = (Eigen::AngleAxisd(x(5) * kDeg, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(x(4) * kDeg, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(x(3) * kDeg, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return T;
}

// A 2D scanner (its x-y plane, field of view fov_deg, 1 deg beams) on a
// motor turning about axis_body through the body origin, the body at
// T_world_body per line in a 7 x 5.5 x 2.5 m room with a 1 m box on the floor. Lines are
// ray-cast with the true extrinsic and 1 cm range noise; the returns carry
// the platform's (wrong) extrinsic, as a payload plugin would give them.
std::vector<CalibrationReturn> Rig(const Vector6d& truth, const Vector6d& platform,
                                   const std::vector<double>& motor_deg, const Eigen::Vector3d& axis_body,
                                   double fov_deg, const std::vector<Eigen::Isometry3d>& T_world_body) {
  struct Box {
    Eigen::Vector3d low, high;
    bool inside;  // the room (rays leave through its walls) or an obstacle in it
  };
  const Box boxes[] = {{{-3.0, -2.5, -1.0}, {4.0, 3.0, 1.5}, true}, {{1.5, -2.0, -1.0}, {2.5, -1.0, 0.0}, false}};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<CalibrationReturn> returns;
  for (std::size_t k = 0; k < motor_deg.size(); ++k) {
    const Eigen::Isometry3d motor = T_world_body[k] * Eigen::AngleAxisd(motor_deg[k] * kDeg, axis_body);
    const Eigen::Isometry3d T_true = motor * MotorLidar(truth), T_platform = motor * MotorLidar(platform);
    for (double a = -fov_deg / 2; a <= fov_deg / 2; a += 1.0) {
      const Eigen::Vector3d d_lidar(std::cos(a * kDeg), std::sin(a * kDeg), 0.0);
      const Eigen::Vector3d o = T_true.translation(), d = T_true.linear() * d_lidar;
      double range = 1e9;
      for (const Box& b : boxes) {
        if (b.inside) {
          for (int i = 0; i < 3; ++i) {
            if (d(i) > 1e-9) range = std::min(range, (b.high(i) - o(i)) / d(i));
            if (d(i) < -1e-9) range = std::min(range, (b.low(i) - o(i)) / d(i));
          }
        } else {  // slab test: the entry distance
          double t0 = 0.0, t1 = 1e9;
          for (int i = 0; i < 3; ++i) {
            if (std::abs(d(i)) < 1e-12) {
              if (o(i) < b.low(i) || o(i) > b.high(i)) t0 = 2e9;
              continue;
            }
            const double ta = (b.low(i) - o(i)) / d(i), tb = (b.high(i) - o(i)) / d(i);
            t0 = std::max(t0, std::min(ta, tb));
            t1 = std::min(t1, std::max(ta, tb));
          }
          if (t0 <= t1) range = std::min(range, t0);
        }
      }
      CalibrationReturn r;
      r.p_lidar = ((range + noise(rng)) * d_lidar).cast<float>();
      r.q_world_lidar = Eigen::Quaterniond(T_platform.linear()).cast<float>();
      r.t_world_lidar = T_platform.translation().cast<float>();
      r.scan = static_cast<std::uint32_t>(k);
      returns.push_back(r);
    }
  }
  return returns;
}

std::string Describe(const CalibrationResult& r) {
  std::string s = "rms " + std::to_string(r.rms_start_m) + " -> " + std::to_string(r.rms_end_m) + " m, " +
                  std::to_string(r.neighbourhoods) + " planes, " + std::to_string(r.rounds) + " rounds, " +
                  std::to_string(r.iterations) + " steps; information ratios and directions:";
  for (int k = 0; k < 6; ++k) {
    s += "\n  " + std::to_string(r.information_ratio(k)) + ":";
    for (int a = 0; a < 6; ++a) s += " " + std::to_string(r.directions(a, k));
  }
  return s;
}

// Lines of a motor turning one degree per line for `turns` turns.
std::vector<double> Turns(int turns) {
  std::vector<double> motor;
  for (int k = 0; k < 360 * turns; ++k) motor.push_back(k);
  return motor;
}

// A moving rig's result: converged, all six directions estimated, the
// extrinsic within 5 mm and 0.2 deg of the truth.
void ExpectAllSixRecovered(const CalibrationResult& r, const Vector6d& truth, const Vector6d& platform) {
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.observable, 6) << Describe(r);
  const Eigen::Isometry3d error = MotorLidar(truth).inverse() * MotorLidar(platform) * r.T_lidar_corrected;
  EXPECT_LT(error.translation().norm(), 0.005) << error.translation().transpose();
  EXPECT_LT(Eigen::AngleAxisd(error.linear()).angle() / kDeg, 0.2);
}

TEST(ExtrinsicCalibrator, RecoversARotatingRigsExtrinsicFromAMovingBody) {
  Vector6d truth, platform;
  truth << 0.04, 0.0, -0.05, 90.0, 0.0, 0.0;       // rolled 90 deg: the fan is vertical
  platform << 0.01, 0.03, -0.05, 91.5, -1.5, 1.0;  // 3 cm and 1-1.5 deg off
  // The body walks 3 m across the room, turns 90 deg and sways by up to 10
  // deg in roll and pitch while the motor turns three times (known poses, as
  // a run's trajectory gives them).
  const std::vector<double> motor = Turns(3);
  std::vector<Eigen::Isometry3d> body;
  for (std::size_t k = 0; k < motor.size(); ++k) {
    const double s = static_cast<double>(k) / static_cast<double>(motor.size());
    body.push_back(Eigen::Translation3d(-1.0 + 3.0 * s, -0.5 + std::sin(3.0 * s), 0.2 * s) *
                   Eigen::AngleAxisd(0.5 * M_PI * s, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(10.0 * kDeg * std::sin(7.0 * s), Eigen::Vector3d::UnitX()) *
                   Eigen::AngleAxisd(10.0 * kDeg * std::sin(5.0 * s), Eigen::Vector3d::UnitY()));
  }
  const std::vector<CalibrationReturn> returns = Rig(truth, platform, motor, Eigen::Vector3d::UnitZ(), 270.0, body);
  const CalibrationResult r = ExtrinsicCalibrator().Calibrate(returns);
  ExpectAllSixRecovered(r, truth, platform);
  EXPECT_LT(r.rms_end_m, 0.5 * r.rms_start_m);
}

TEST(ExtrinsicCalibrator, RecoversANoddingRigsExtrinsicFromAMovingBody) {
  // A level 270 deg scanner nodding +-40 deg about the body's y (the motor
  // frame turned so that its z is the body's y, as in tilting_urg04lx.yaml)
  // on a body walking across the room: the same solver, another motor.
  Vector6d truth, platform;
  truth << 0.03, -0.02, 0.06, 90.0, 0.0, 0.0;   // motor_lidar: the LiDAR level at angle 0
  platform << 0.0, 0.0, 0.03, 88.5, 1.0, -1.0;  // 3 cm and 1-1.5 deg off
  std::vector<double> motor;
  std::vector<Eigen::Isometry3d> body;
  const Eigen::Isometry3d body_motor(Eigen::AngleAxisd(-0.5 * M_PI, Eigen::Vector3d::UnitX()));
  for (int k = 0; k < 1200; ++k) {
    const double s = k / 1200.0;
    motor.push_back(40.0 * std::sin(2.0 * M_PI * k / 100.0));  // 12 nods
    body.push_back(Eigen::Translation3d(-1.5 + 3.0 * s, -1.0 + 1.5 * s, 0.1 * std::sin(4.0 * s)) *
                   Eigen::AngleAxisd(0.4 * M_PI * s, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(8.0 * kDeg * std::sin(9.0 * s), Eigen::Vector3d::UnitX()) * body_motor);
  }
  const std::vector<CalibrationReturn> returns = Rig(truth, platform, motor, Eigen::Vector3d::UnitZ(), 270.0, body);
  const CalibrationResult r = ExtrinsicCalibrator().Calibrate(returns);
  ExpectAllSixRecovered(r, truth, platform);
}

// The correction's error against the truth as [translation (m), rotation
// vector (deg)], in the LiDAR frame.
Vector6d ErrorOf(const Vector6d& truth, const Vector6d& platform, const Eigen::Isometry3d& correction) {
  const Eigen::Isometry3d e = MotorLidar(truth).inverse() * MotorLidar(platform) * correction;
  const Eigen::AngleAxisd aa(e.linear());
  Vector6d v;
  v << e.translation(), aa.angle() * aa.axis() / kDeg;
  return v;
}

TEST(ExtrinsicCalibrator, EstimatesOnlyWhatAStandingRotatingRigObserves) {
  // Standing still, the rig sees the walls once per turn and only the floor
  // and ceiling near the axis from both sides of its fan: of the six
  // directions only the beams' angle within the fan (rotation about the
  // LiDAR's z) changes how the two views agree. It is estimated; the other
  // five keep the platform's values, and are said to.
  Vector6d truth, platform;
  truth << 0.04, 0.0, -0.05, 90.0, 0.0, 0.0;
  platform << 0.01, 0.03, -0.05, 91.5, -1.5, 1.0;
  const std::vector<double> motor = Turns(1);
  const std::vector<CalibrationReturn> returns =
      Rig(truth, platform, motor, Eigen::Vector3d::UnitZ(), 270.0,
          std::vector<Eigen::Isometry3d>(motor.size(), Eigen::Isometry3d::Identity()));
  const CalibrationResult r = ExtrinsicCalibrator().Calibrate(returns);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.observable, 1) << Describe(r);
  EXPECT_GT(std::abs(r.directions(5, 5)), 0.99)
      << "the observed direction is not the rotation about z: " << Describe(r);
  const Vector6d before = ErrorOf(truth, platform, Eigen::Isometry3d::Identity());
  const Vector6d after = ErrorOf(truth, platform, r.T_lidar_corrected);
  EXPECT_GT(std::abs(before(5)), 1.0);
  EXPECT_LT(std::abs(after(5)), 0.2) << "before " << before.transpose() << "\nafter " << after.transpose();
  // The held directions: the correction (in prior sigmas, the directions'
  // units: 0.1 m, 10 deg) has no component along them.
  const Eigen::AngleAxisd aa(r.T_lidar_corrected.linear());
  Vector6d c;
  c << r.T_lidar_corrected.translation() / 0.1, aa.angle() * aa.axis() / (10.0 * kDeg);
  const Vector6d held = c - c.dot(r.directions.col(5)) * r.directions.col(5);
  EXPECT_LT(held.norm(), 5e-3) << c.transpose();
  EXPECT_LT(r.rms_end_m, 0.5 * r.rms_start_m);
}

TEST(ExtrinsicCalibrator, SaysWhenTheScansShareNoSurface) {
  std::vector<CalibrationReturn> returns(100);
  for (std::size_t i = 0; i < returns.size(); ++i) {
    returns[i].p_lidar = Eigen::Vector3f(static_cast<float>(i), 0.0f, 0.0f);  // 1 m apart: no neighbours
    returns[i].scan = static_cast<std::uint32_t>(i);
  }
  const CalibrationResult r = ExtrinsicCalibrator().Calibrate(returns);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("(100 returns): the scans do not see common surfaces"), std::string::npos) << r.failure;
  CalibrationOptions bad;
  bad.sigma_m = 0.0;
  EXPECT_THROW(ExtrinsicCalibrator{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace unimap::calibration
