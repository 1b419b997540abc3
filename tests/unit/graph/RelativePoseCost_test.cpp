#include "graph/RelativePoseCost.hpp"

#include <cmath>
#include <memory>
#include <random>

#include <ceres/cost_function.h>
#include <gtest/gtest.h>

namespace unimap::graph {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

Eigen::Isometry3d MakePose(const Eigen::Vector3d& p, const Eigen::Vector3d& rotation_vector) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(rotation_vector.norm(), rotation_vector.normalized()).toRotationMatrix();
  T.translation() = p;
  return T;
}

// Raw parameter blocks of one pose (Eigen quaternion order x y z w).
struct RawPose {
  double p[3];
  double q[4];
};

RawPose ToRaw(const Eigen::Isometry3d& T) {
  RawPose raw{};
  const Eigen::Quaterniond q(T.linear());
  for (int i = 0; i < 3; ++i) raw.p[i] = T.translation()[i];
  for (int i = 0; i < 4; ++i) raw.q[i] = q.coeffs()[i];
  return raw;
}

Vector6d Residual(const RelativePoseCost& cost, const RawPose& a, const RawPose& b) {
  Vector6d r;
  cost(a.p, a.q, b.p, b.q, r.data());
  return r;
}

// A random upper-triangular square root with a well-conditioned diagonal.
Matrix6d RandomSqrtInformation(std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix6d S = Matrix6d::Zero();
  for (int r = 0; r < 6; ++r) {
    S(r, r) = 2.0 + u(*rng);
    for (int c = r + 1; c < 6; ++c) S(r, c) = 0.3 * u(*rng);
  }
  return S;
}

const Eigen::Isometry3d kT_world_a = MakePose({1.0, -2.0, 0.5}, {0.2, -0.1, 0.7});
const Eigen::Isometry3d kT_a_b = MakePose({0.8, 0.3, -0.2}, {-0.05, 0.1, 0.4});

TEST(RelativePoseCost, ZeroAtTheMeasuredRelativePose) {
  std::mt19937_64 rng(3);
  const RelativePoseCost cost(kT_a_b, RandomSqrtInformation(&rng));
  const Vector6d r = Residual(cost, ToRaw(kT_world_a), ToRaw(kT_world_a * kT_a_b));
  EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-14);
}

TEST(RelativePoseCost, KnownResidualForAKnownPerturbation) {
  // Identity information: r = [R_world_a^T d ; 2 sin(theta/2) axis] when b
  // moves by d in the world and turns by theta about axis in its own frame.
  const RelativePoseCost cost(kT_a_b, Matrix6d::Identity());
  const Eigen::Vector3d d_world(0.03, -0.02, 0.05);
  const double theta = 0.3;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, -2.0).normalized();
  Eigen::Isometry3d T_world_b = kT_world_a * kT_a_b;
  T_world_b.linear() = T_world_b.linear() * Eigen::AngleAxisd(theta, axis).toRotationMatrix();
  T_world_b.translation() += d_world;
  const Vector6d r = Residual(cost, ToRaw(kT_world_a), ToRaw(T_world_b));
  const Eigen::Vector3d expected_translation = kT_world_a.linear().transpose() * d_world;
  const Eigen::Vector3d expected_rotation = 2.0 * std::sin(theta / 2.0) * axis;
  EXPECT_LT((r.head<3>() - expected_translation).cwiseAbs().maxCoeff(), 1e-14);
  // The sign of a quaternion is free: either sign of the vector part is a
  // valid encoding of the same error.
  const double rotation_error = std::min((r.tail<3>() - expected_rotation).cwiseAbs().maxCoeff(),
                                         (r.tail<3>() + expected_rotation).cwiseAbs().maxCoeff());
  EXPECT_LT(rotation_error, 1e-14);

  // The information multiplies the whitened error.
  std::mt19937_64 rng(5);
  const Matrix6d S = RandomSqrtInformation(&rng);
  const RelativePoseCost weighted(kT_a_b, S);
  const Vector6d rw = Residual(weighted, ToRaw(kT_world_a), ToRaw(T_world_b));
  EXPECT_LT((rw - S * r).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(RelativePoseCost, AutodiffJacobianMatchesCentralDifferences) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  const Matrix6d S = RandomSqrtInformation(&rng);
  const RelativePoseCost functor(kT_a_b, S);
  const std::unique_ptr<ceres::CostFunction> cost(RelativePoseCost::Create(kT_a_b, S));
  for (int trial = 0; trial < 10; ++trial) {
    // Away from the measurement, so every Jacobian term is exercised.
    const Eigen::Isometry3d T_world_a =
        kT_world_a * MakePose({n(rng), n(rng), n(rng)}, 0.3 * Eigen::Vector3d(n(rng), n(rng), n(rng)));
    const Eigen::Isometry3d T_world_b =
        T_world_a * kT_a_b * MakePose({n(rng), n(rng), n(rng)}, 0.3 * Eigen::Vector3d(n(rng), n(rng), n(rng)));
    RawPose a = ToRaw(T_world_a);
    RawPose b = ToRaw(T_world_b);
    double* blocks[4] = {a.p, a.q, b.p, b.q};
    const int sizes[4] = {3, 4, 3, 4};
    Vector6d residual;
    Eigen::Matrix<double, 6, 3, Eigen::RowMajor> J_p_a, J_p_b;
    Eigen::Matrix<double, 6, 4, Eigen::RowMajor> J_q_a, J_q_b;
    double* jacobians[4] = {J_p_a.data(), J_q_a.data(), J_p_b.data(), J_q_b.data()};
    ASSERT_TRUE(cost->Evaluate(blocks, residual.data(), jacobians));
    EXPECT_LT((residual - Residual(functor, a, b)).cwiseAbs().maxCoeff(), 1e-14);

    // Central differences on the raw parameters (the functor is a smooth
    // function of all 14, unit quaternion or not): error O(h^2) ~ 1e-10.
    const double h = 1e-6;
    for (int block = 0; block < 4; ++block) {
      for (int k = 0; k < sizes[block]; ++k) {
        const double saved = blocks[block][k];
        blocks[block][k] = saved + h;
        const Vector6d plus = Residual(functor, a, b);
        blocks[block][k] = saved - h;
        const Vector6d minus = Residual(functor, a, b);
        blocks[block][k] = saved;
        const Vector6d numeric = (plus - minus) / (2.0 * h);
        for (int row = 0; row < 6; ++row) {
          const double analytic = jacobians[block][row * sizes[block] + k];
          EXPECT_NEAR(analytic, numeric[row], 1e-6) << "trial " << trial << " block " << block << " k " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace unimap::graph
