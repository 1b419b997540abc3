#include "matching/PseudoMeasurement.hpp"

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "estimation/Eskf.hpp"

namespace unimap::matching {
namespace {

Matrix6d RandomSpd(std::mt19937_64* rng, double scale) {
  std::normal_distribution<double> n(0.0, 1.0);
  Matrix6d A;
  for (int i = 0; i < 36; ++i) A(i) = n(*rng);
  return scale * (A * A.transpose() + 0.5 * Matrix6d::Identity());
}

TEST(RecoverPseudoMeasurement, EskfUpdateReproducesTheGpfPosterior) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    estimation::Eskf filter(estimation::EskfOptions{});
    estimation::ErrorCovariance P = estimation::ErrorCovariance::Identity() * 1e-2;
    const Matrix6d S_s = RandomSpd(&rng, 1e-3);
    const int rows[6] = {0, 1, 2, 6, 7, 8};
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) P(rows[r], rows[c]) = S_s(r, c);
    filter.Initialize(estimation::NavState{}, P);
    // A posterior with more information than the prior.
    const Matrix6d S_p = (S_s.inverse() + RandomSpd(&rng, 50.0)).inverse();
    Vector6d mu_p;
    for (int i = 0; i < 6; ++i) mu_p(i) = 0.01 * n(rng);
    const PseudoMeasurement m = RecoverPseudoMeasurement(Vector6d::Zero(), S_s, mu_p, S_p, 1e-9);
    ASSERT_TRUE(m.ok);
    EXPECT_EQ(m.repaired_eigenvalues, 0);
    const auto update = filter.UpdatePoseError(m.z, m.R);
    ASSERT_TRUE(update.applied);
    EXPECT_LT((update.error_correction - mu_p).cwiseAbs().maxCoeff(), 1e-9) << trial;
    EXPECT_LT((update.pose_covariance_before_reset - S_p).cwiseAbs().maxCoeff(), 1e-9) << trial;
  }
}

TEST(RecoverPseudoMeasurement, NonzeroSampleMeanFollowsTheFormula) {
  std::mt19937_64 rng(3);
  const Matrix6d S_s = RandomSpd(&rng, 1e-2);
  const Matrix6d S_p = (S_s.inverse() + RandomSpd(&rng, 10.0)).inverse();
  Vector6d mu_s, mu_p;
  mu_s << 0.01, -0.02, 0.0, 0.001, 0.0, -0.002;
  mu_p << 0.03, 0.01, -0.01, 0.0, 0.002, 0.001;
  const PseudoMeasurement m = RecoverPseudoMeasurement(mu_s, S_s, mu_p, S_p, 1e-9);
  ASSERT_TRUE(m.ok);
  // Kalman update of N(mu_s, S_s) with (z, R) gives N(mu_p, S_p).
  const Matrix6d K = S_s * (S_s + m.R).inverse();
  EXPECT_LT((mu_s + K * (m.z - mu_s) - mu_p).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(((Matrix6d::Identity() - K) * S_s - S_p).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(RecoverPseudoMeasurement, RepairsDirectionsWithoutInformation) {
  Matrix6d S_s = Matrix6d::Identity() * 0.01;
  Matrix6d S_p = Matrix6d::Identity() * 0.004;
  S_p(2, 2) = 0.012;  // the scan "lost" information along z: not positive definite
  Vector6d mu_p = Vector6d::Zero();
  mu_p(0) = 0.05;
  const PseudoMeasurement m = RecoverPseudoMeasurement(Vector6d::Zero(), S_s, mu_p, S_p, 1e-6);
  ASSERT_TRUE(m.ok);
  EXPECT_EQ(m.repaired_eigenvalues, 1);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(m.R);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  EXPECT_GT(m.R(2, 2), 1e3 * m.R(0, 0));  // practically no information along z
  const Matrix6d K = S_s * (S_s + m.R).inverse();
  EXPECT_NEAR((K * m.z)(0), 0.05, 1e-9);  // the informative directions are intact
}

TEST(RecoverPseudoMeasurement, RejectsIndefiniteInputs) {
  Matrix6d bad = Matrix6d::Identity();
  bad(0, 0) = -1.0;
  EXPECT_FALSE(RecoverPseudoMeasurement(Vector6d::Zero(), bad, Vector6d::Zero(), Matrix6d::Identity(), 1e-6).ok);
}

}  // namespace
}  // namespace unimap::matching
