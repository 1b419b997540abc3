// Conformance: encoder synchronisation. With a constant-rate motor the
// plugin's motor angle and mount must follow it exactly, across wrap-around
// and irregular sample spacing; times outside the encoder are errors.
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "PayloadConformanceTest.hpp"
#include "SyntheticRig.hpp"
#include "unimap/Errors.hpp"

namespace unimap::conformance {
namespace {

constexpr double kExactTolerance = 1e-9;  // "exact": double rounding only
constexpr double kRate = SyntheticRig::kMotorRateRadS;

// Query times over the encoder coverage: random ones, every sample time,
// both ends, and times right around every wrap of the raw angle.
std::vector<double> QueryTimes(const std::vector<EncoderSample>& samples, SyntheticRig::Wrap wrap) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> time_s(SyntheticRig::kEncoderStartS, SyntheticRig::kEncoderEndS);
  std::vector<double> times;
  for (int i = 0; i < 300; ++i) times.push_back(time_s(rng));
  for (const EncoderSample& s : samples) times.push_back(s.time_s);
  for (double t_wrap : SyntheticRig::WrapTimes(wrap)) {
    for (double dt : {-1e-3, -1e-6, -1e-9, 0.0, 1e-9, 1e-6, 1e-3}) times.push_back(t_wrap + dt);
  }
  return times;
}

std::string WrapName(SyntheticRig::Wrap wrap) {
  return wrap == SyntheticRig::Wrap::kZeroToTwoPi ? "raw angles in [0, 2pi)" : "raw angles in [-pi, pi)";
}

}  // namespace

// theta(t2) - theta(t1) = s * rate * (t2 - t1), s = +-1 fixed (the encoder
// direction), and T_body_lidar(t2) * T_body_lidar(t1)^-1 = a rotation by
// s * rate * (t2 - t1) about one fixed line (the motor axis in the body
// frame): true for any T_body_motor and T_motor_lidar.
TEST_P(PayloadConformanceTest, EncoderInterpolationExact) {
  if (!plugin().UsesEncoder()) GTEST_SKIP() << "payload has no motor";
  for (const SyntheticRig::Wrap wrap : {SyntheticRig::Wrap::kZeroToTwoPi, SyntheticRig::Wrap::kMinusPiToPi}) {
    SCOPED_TRACE(WrapName(wrap));
    const std::vector<EncoderSample> samples = SyntheticRig::EncoderSamples(wrap, 11);
    const EncoderTrack track(samples);
    const double t_ref = 1.0;
    const double theta_ref = plugin().MotorAngleAt(track, t_ref);

    // Direction s from a 0.33 rad step.
    const double ratio =
        std::remainder(plugin().MotorAngleAt(track, t_ref + 0.1) - theta_ref, 2.0 * M_PI) / (kRate * 0.1);
    ASSERT_NEAR(std::fabs(ratio), 1.0, kExactTolerance)
        << Label() << ": the motor angle changes " << ratio
        << " times as fast as the encoder; it must follow it one to one";
    const double s = ratio > 0.0 ? 1.0 : -1.0;

    // The body-frame motor axis and a point on it, from a 1 rad step.
    const Eigen::Isometry3d T_ref_inv = plugin().BodyFromLidarAt(track, t_ref).inverse();
    const Eigen::Isometry3d D_a = plugin().BodyFromLidarAt(track, t_ref + 1.0 / kRate) * T_ref_inv;
    const Eigen::AngleAxisd step(D_a.linear());
    ASSERT_NEAR(step.angle(), 1.0, kExactTolerance)
        << Label() << ": a 1 rad motor step turns the LiDAR by " << step.angle() << " rad";
    const Eigen::Vector3d axis_body = s * step.axis();
    const Eigen::Matrix3d I_minus_R = Eigen::Matrix3d::Identity() - D_a.linear();
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(I_minus_R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-6);
    const Eigen::Vector3d on_axis = svd.solve(D_a.translation());  // (I - R) c = t

    double worst_angle = 0.0, worst_rotation = 0.0, worst_axis_point = 0.0, worst_rigid = 0.0;
    double t_angle = 0.0, t_rotation = 0.0, t_axis_point = 0.0;
    for (double t : QueryTimes(samples, wrap)) {
      const double expected_delta = s * kRate * (t - t_ref);
      const double angle_error =
          std::fabs(std::remainder(plugin().MotorAngleAt(track, t) - theta_ref - expected_delta, 2.0 * M_PI));
      if (angle_error > worst_angle) {
        worst_angle = angle_error;
        t_angle = t;
      }

      const Eigen::Isometry3d T_body_lidar = plugin().BodyFromLidarAt(track, t);
      const Eigen::Matrix3d R = T_body_lidar.linear();
      worst_rigid = std::max(
          {worst_rigid, (R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), std::fabs(R.determinant() - 1.0)});
      const Eigen::Isometry3d D = T_body_lidar * T_ref_inv;
      const double rotation_error =
          (D.linear() - Eigen::AngleAxisd(expected_delta, axis_body).toRotationMatrix()).norm();
      if (rotation_error > worst_rotation) {
        worst_rotation = rotation_error;
        t_rotation = t;
      }
      const double axis_point_error = (D * on_axis - on_axis).norm();
      if (axis_point_error > worst_axis_point) {
        worst_axis_point = axis_point_error;
        t_axis_point = t;
      }
    }
    EXPECT_LT(worst_angle, kExactTolerance)
        << Label() << ": MotorAngleAt(t) - MotorAngleAt(" << t_ref << ") differs from " << s << " * " << kRate
        << " rad/s * (t - " << t_ref << ") by " << worst_angle << " rad at t = " << t_angle << " s";
    EXPECT_LT(worst_rigid, kExactTolerance) << Label() << ": BodyFromLidarAt is not a rigid transform";
    EXPECT_LT(worst_rotation, kExactTolerance)
        << Label() << ": BodyFromLidarAt(t) * BodyFromLidarAt(" << t_ref << ")^-1 is not a rotation by " << s
        << " * rate * dt about the fixed body axis (" << axis_body.transpose() << "): off by " << worst_rotation
        << " at t = " << t_rotation << " s";
    EXPECT_LT(worst_axis_point, kExactTolerance)
        << Label() << ": the motor axis line moves in the body frame (point " << on_axis.transpose() << " moved by "
        << worst_axis_point << " m at t = " << t_axis_point << " s)";
  }
}

TEST_P(PayloadConformanceTest, EncoderCoverageEnforced) {
  if (!plugin().UsesEncoder()) GTEST_SKIP() << "payload has no motor";
  const EncoderTrack track(SyntheticRig::EncoderSamples(SyntheticRig::Wrap::kZeroToTwoPi, 3));
  for (double t : {track.start_time_s() - 0.01, track.end_time_s() + 0.01, -100.0, 1e6}) {
    EXPECT_THROW(plugin().MotorAngleAt(track, t), InputError)
        << Label() << ": MotorAngleAt(" << t << ") outside encoder coverage [" << track.start_time_s() << ", "
        << track.end_time_s() << "] must throw InputError";
    EXPECT_THROW(plugin().BodyFromLidarAt(track, t), InputError)
        << Label() << ": BodyFromLidarAt(" << t << ") outside encoder coverage must throw InputError";
  }
  const EncoderTrack empty;
  EXPECT_THROW(plugin().MotorAngleAt(empty, 1.0), InputError)
      << Label() << ": MotorAngleAt without encoder samples must throw InputError";
  EXPECT_THROW(plugin().BodyFromLidarAt(empty, 1.0), InputError)
      << Label() << ": BodyFromLidarAt without encoder samples must throw InputError";
}

// A payload without a motor: motor angle 0 and one rigid T_body_lidar at
// every time, with no encoder at all.
TEST_P(PayloadConformanceTest, StaticMountWithoutMotor) {
  if (plugin().UsesEncoder()) GTEST_SKIP() << "payload has a motor (see EncoderInterpolationExact)";
  const EncoderTrack empty;
  const Eigen::Isometry3d T_body_lidar = plugin().BodyFromLidarAt(empty, 0.0);
  const Eigen::Matrix3d R = T_body_lidar.linear();
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), kExactTolerance)
      << Label() << ": BodyFromLidarAt is not a rotation";
  EXPECT_NEAR(R.determinant(), 1.0, kExactTolerance) << Label() << ": BodyFromLidarAt is not a rotation";
  for (double t : {-5.0, 0.9, 1.0, 1e6}) {
    EXPECT_EQ(plugin().MotorAngleAt(empty, t), 0.0) << Label() << ": no motor, yet angle at t = " << t;
    EXPECT_TRUE(plugin().BodyFromLidarAt(empty, t).matrix() == T_body_lidar.matrix())
        << Label() << ": no motor, yet T_body_lidar changes at t = " << t;
  }
}

}  // namespace unimap::conformance
