#include "estimation/Eskf.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "AnalyticMotion.hpp"
#include "estimation/So3.hpp"

namespace unimap::estimation {
namespace {

using testing::Motion;
using testing::MotionSample;
using testing::PerfectImu;

NavState TruthState(const Motion& motion, double t) {
  const MotionSample m = motion(t);
  NavState s;
  s.time_s = t;
  s.p_world_body_m = m.p;
  s.v_world_m_s = m.v;
  s.q_world_body = Eigen::Quaterniond(m.R);
  return s;
}

// Noise-free propagation over 10 s at 200 Hz; returns the final position error.
double PropagationError(const Motion& motion, double* rotation_error_rad) {
  EskfOptions options;
  options.gravity_m_s2 = testing::kGravity;
  Eskf filter(options);
  filter.Initialize(TruthState(motion, 0.0));
  for (int k = 0; k <= 2000; ++k) EXPECT_TRUE(filter.Propagate(PerfectImu(motion, 0.005 * k)));
  const NavState truth = TruthState(motion, 10.0);
  *rotation_error_rad = LogQ(filter.state().q_world_body.conjugate() * truth.q_world_body).norm();
  return (filter.state().p_world_body_m - truth.p_world_body_m).norm();
}

TEST(Eskf, PropagationIsExactOnNoiseFreeAnalyticMotion) {
  const std::pair<const char*, Motion> motions[] = {{"constant rotation", testing::ConstantRotation},
                                                    {"circle", testing::Circle},
                                                    {"figure eight", testing::FigureEight}};
  for (const auto& [name, motion] : motions) {
    double rotation_error = 0.0;
    const double position_error = PropagationError(motion, &rotation_error);
    EXPECT_LT(position_error, 1e-3) << name;
    EXPECT_LT(rotation_error, 1e-6) << name;
  }
}

TEST(Eskf, PoseUpdateFusesLikeAKalmanFilter) {
  EskfOptions options;
  Eskf filter(options);
  filter.Initialize(NavState{});
  const Matrix6d P_pose = filter.PoseCovariance();
  Vector6d z;
  z << 0.02, -0.01, 0.03, 0.004, -0.002, 0.001;
  const Matrix6d R = P_pose;  // equal weights: the posterior is halfway
  const PoseUpdateResult result = filter.UpdatePoseError(z, R);
  ASSERT_TRUE(result.applied);
  EXPECT_TRUE(result.error_correction.isApprox(0.5 * z, 1e-12));
  EXPECT_TRUE(result.pose_covariance_before_reset.isApprox(0.5 * P_pose, 1e-12));
  EXPECT_TRUE(filter.state().p_world_body_m.isApprox(0.5 * z.head<3>(), 1e-12));
  EXPECT_NEAR(LogQ(filter.state().q_world_body).norm(), 0.5 * z.tail<3>().norm(), 1e-12);
}

TEST(Eskf, RejectsNonIncreasingOrGappedImu) {
  Eskf filter(EskfOptions{});
  filter.Initialize(NavState{});
  ImuSample s;
  s.time_s = 1.0;
  EXPECT_TRUE(filter.Propagate(s));
  EXPECT_FALSE(filter.Propagate(s));  // same time
  s.time_s = 1.5;                     // gap of 0.5 s > max_imu_gap_s
  EXPECT_FALSE(filter.Propagate(s));
  EXPECT_EQ(filter.state().time_s, 1.0);
}

// Chi-square quantile (Wilson-Hilferty), accurate to ~1e-3 relative for large dof.
double ChiSquareQuantile(double dof, double z) {
  const double c = 2.0 / (9.0 * dof);
  return dof * std::pow(1.0 - c + z * std::sqrt(c), 3.0);
}

TEST(Eskf, PredictPoseMovesByTheBodyIncrementAndAddsItsCovariance) {
  Eskf eskf(EskfOptions{});
  NavState start;
  start.time_s = 1.0;
  start.p_world_body_m = Eigen::Vector3d(1.0, 2.0, 3.0);
  start.q_world_body = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()));
  eskf.Initialize(start, ErrorCovariance::Zero());
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.translation() = Eigen::Vector3d(0.5, 0.0, 0.1);  // forward in the body frame
  step.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Matrix6d q = Matrix6d::Zero();
  q.diagonal() << 0.01, 0.04, 0.09, 1e-4, 4e-4, 9e-4;
  eskf.PredictPose(1.5, step, q);
  const NavState& s = eskf.state();
  EXPECT_EQ(s.time_s, 1.5);
  // Body x points along world y after the 90 deg yaw: p += R dp.
  EXPECT_TRUE(s.p_world_body_m.isApprox(Eigen::Vector3d(1.0, 2.5, 3.1), 1e-12));
  EXPECT_NEAR(Eigen::AngleAxisd(s.q_world_body).angle(), M_PI / 2.0 + 0.1, 1e-12);
  EXPECT_TRUE(s.v_world_m_s.isApprox(Eigen::Vector3d(0.0, 1.0, 0.2), 1e-12));
  // From zero covariance, the position block is R Q_p R^T (x and y swap) and
  // the attitude block Q_theta.
  const Matrix6d p = eskf.PoseCovariance();
  EXPECT_NEAR(p(0, 0), 0.04, 1e-12);
  EXPECT_NEAR(p(1, 1), 0.01, 1e-12);
  EXPECT_NEAR(p(2, 2), 0.09, 1e-12);
  EXPECT_TRUE((p.bottomRightCorner<3, 3>().isApprox(q.bottomRightCorner<3, 3>(), 1e-12)));
  // A second step carries the attitude uncertainty into position: dp' = dp - R [dp_inc]x dtheta.
  eskf.PredictPose(2.0, step, Matrix6d::Zero());
  EXPECT_GT(eskf.PoseCovariance()(0, 0) + eskf.PoseCovariance()(1, 1), 0.05 - 1e-12);
}

TEST(Eskf, FilterIsConsistentOverMonteCarloRuns) {
  EskfOptions options;
  options.sigma_accel_m_s2 = 0.05;
  options.sigma_gyro_rad_s = 0.005;
  options.accel_bias_walk_m_s2_sqrt_s = 1e-3;
  options.gyro_bias_walk_rad_s_sqrt_s = 1e-4;
  options.gravity_m_s2 = testing::kGravity;
  const int runs = 50;
  const double dt = 0.005;
  Matrix6d R = Matrix6d::Zero();
  R.diagonal() << 0.05, 0.05, 0.05, 0.01, 0.01, 0.01;
  R = R.array().square().matrix();
  const Eigen::LLT<Matrix6d> R_llt(R);
  double nees_sum = 0.0;
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto noise3 = [&]() { return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)); };
  for (int run = 0; run < runs; ++run) {
    Eskf filter(options);
    const NavState truth0 = TruthState(testing::FigureEight, 0.0);
    // True biases and initial error drawn from the filter's initial covariance.
    Eigen::Vector3d ba = options.initial_sigma_accel_bias_m_s2 * noise3();
    Eigen::Vector3d bg = options.initial_sigma_gyro_bias_rad_s * noise3();
    NavState start = truth0;
    start.p_world_body_m -= options.initial_sigma_position_m * noise3();
    start.v_world_m_s -= options.initial_sigma_velocity_m_s * noise3();
    start.q_world_body = truth0.q_world_body * ExpQ(-options.initial_sigma_attitude_rad * noise3());
    filter.Initialize(start);
    for (int k = 0; k <= 4000; ++k) {
      const double t = dt * k;
      ImuSample s = PerfectImu(testing::FigureEight, t);
      s.accel_m_s2 += ba + options.sigma_accel_m_s2 * noise3();
      s.gyro_rad_s += bg + options.sigma_gyro_rad_s * noise3();
      ASSERT_TRUE(filter.Propagate(s));
      ba += options.accel_bias_walk_m_s2_sqrt_s * std::sqrt(dt) * noise3();
      bg += options.gyro_bias_walk_rad_s_sqrt_s * std::sqrt(dt) * noise3();
      if (k > 0 && k % 20 == 0) {  // 10 Hz pose measurements with covariance R
        const NavState truth = TruthState(testing::FigureEight, t);
        Vector6d n;
        n << noise3(), noise3();
        n = R_llt.matrixL() * n;
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.translation() = truth.p_world_body_m + n.head<3>();
        T.linear() = (truth.q_world_body * ExpQ(n.tail<3>())).toRotationMatrix();
        ASSERT_TRUE(filter.UpdatePose(T, R).applied);
      }
    }
    const NavState truth = TruthState(testing::FigureEight, 20.0);
    Eigen::Matrix<double, 15, 1> e;
    e << truth.p_world_body_m - filter.state().p_world_body_m, truth.v_world_m_s - filter.state().v_world_m_s,
        LogQ(filter.state().q_world_body.conjugate() * truth.q_world_body), ba - filter.state().accel_bias_m_s2,
        bg - filter.state().gyro_bias_rad_s;
    nees_sum += e.dot(filter.covariance().ldlt().solve(e));
  }
  const double anees = nees_sum / runs;
  const double lower = ChiSquareQuantile(15.0 * runs, -1.959964) / runs;
  const double upper = ChiSquareQuantile(15.0 * runs, 1.959964) / runs;
  EXPECT_GT(anees, lower);
  EXPECT_LT(anees, upper);
  std::cout << "ANEES " << anees << " in [" << lower << ", " << upper << "]\n";
}

// Figure-eight IMU samples at 200 Hz with white noise (fixed seed).
std::vector<ImuSample> NoisyFigureEight(int count) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<ImuSample> out;
  for (int k = 0; k < count; ++k) {
    ImuSample s = PerfectImu(testing::FigureEight, 0.005 * k);
    s.accel_m_s2 += 0.02 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    s.gyro_rad_s += 0.002 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    out.push_back(s);
  }
  return out;
}

TEST(Eskf, PoseCovarianceRelativeToStartLeavesOutTheInitialPoseUncertainty) {
  EskfOptions options;
  options.gravity_m_s2 = testing::kGravity;
  Eskf filter(options);
  const NavState start = TruthState(testing::FigureEight, 0.0);
  filter.Initialize(start);
  EXPECT_LT(filter.PoseCovarianceRelativeToStart().norm(), 1e-15);
  // The same filter started with no pose uncertainty (velocity and biases as
  // before): without updates the covariance is linear in the start's, so its
  // pose covariance is the first's less the start's pose part, exactly.
  ErrorCovariance without_pose = InitialCovariance(options);
  without_pose.topLeftCorner<3, 3>().setZero();
  without_pose.block<3, 3>(error_index::kTheta, error_index::kTheta).setZero();
  Eskf reference(options);
  reference.Initialize(start, without_pose);
  for (const ImuSample& s : NoisyFigureEight(1001)) {
    ASSERT_TRUE(filter.Propagate(s));
    ASSERT_TRUE(reference.Propagate(s));
  }
  const Matrix6d relative = filter.PoseCovarianceRelativeToStart();
  EXPECT_TRUE(relative.isApprox(reference.PoseCovariance(), 1e-9)) << relative << "\n\n" << reference.PoseCovariance();
  // It is the smaller: the start's attitude sigma (0.01 rad) is left out.
  EXPECT_LT(relative(3, 3), filter.PoseCovariance()(3, 3));
}

TEST(Eskf, PoseCovarianceRelativeToStartBecomesTheFullOneAsUpdatesReplaceThePrior) {
  EskfOptions options;
  options.gravity_m_s2 = testing::kGravity;
  Eskf filter(options);
  filter.Initialize(TruthState(testing::FigureEight, 0.0));
  Matrix6d R = Matrix6d::Zero();
  R.diagonal() << 0.02, 0.02, 0.02, 0.002, 0.002, 0.002;
  R = R.array().square().matrix();
  const std::vector<ImuSample> samples = NoisyFigureEight(4001);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_TRUE(filter.Propagate(samples[k]));
    if (k == 20) {
      // One update: the start's part has shrunk but is still there.
      const Matrix6d full = filter.PoseCovariance();
      const Matrix6d relative = filter.PoseCovarianceRelativeToStart();
      EXPECT_LT(relative(3, 3), 0.9 * full(3, 3));
    }
    if (k > 0 && k % 20 == 0) {
      const Eigen::Isometry3d T = TruthState(testing::FigureEight, samples[k].time_s).T_world_body();
      ASSERT_TRUE(filter.UpdatePose(T, R).applied);
    }
  }
  // 200 updates later the start hardly counts (measured: 0.1-0.2 % of each
  // variance is left of it).
  const Matrix6d full = filter.PoseCovariance();
  const Matrix6d relative = filter.PoseCovarianceRelativeToStart();
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(relative(i, i), full(i, i), 1e-2 * full(i, i)) << i;
}

}  // namespace
}  // namespace unimap::estimation
