#include "calibration/CrossViewPlane.hpp"

#include <random>

#include <gtest/gtest.h>

namespace unimap::calibration {
namespace {

Eigen::Isometry3d RandomPose(std::mt19937* rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(n(*rng), n(*rng), n(*rng), n(*rng)).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(n(*rng), n(*rng), n(*rng));
  return T;
}

// Returns on the world plane z = 0 (plus noise_m across it), each seen from a
// random LiDAR pose.
std::vector<CrossViewPlane::Member> OnPlane(std::mt19937* rng, int count, double noise_m) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::normal_distribution<double> noise(0.0, noise_m);
  std::vector<CrossViewPlane::Member> members;
  for (int k = 0; k < count; ++k) {
    const Eigen::Isometry3d T = RandomPose(rng);
    members.push_back({T.inverse() * Eigen::Vector3d(u(*rng), u(*rng), noise(*rng)), T});
  }
  return members;
}

TEST(CrossViewPlane, JacobianMatchesNumericDifferences) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 10; ++trial) {
    const CrossViewPlane plane(OnPlane(&rng, 3 + trial, 0.01), OnPlane(&rng, 8 + trial, 0.01));
    const Eigen::Matrix<double, Eigen::Dynamic, 6> J = plane.Jacobian(0.02);
    const double h = 1e-6;
    for (int a = 0; a < 6; ++a) {
      Vector6d d = Vector6d::Zero();
      d(a) = h;
      const Eigen::VectorXd numeric =
          (plane.Residuals(d, plane.normal(), 0.02) - plane.Residuals(-d, plane.normal(), 0.02)) / (2 * h);
      for (Eigen::Index i = 0; i < J.rows(); ++i) {
        EXPECT_NEAR(J(i, a), numeric(i), 1e-5 * (1.0 + std::abs(numeric(i)))) << "row " << i << " column " << a;
      }
    }
  }
}

TEST(CrossViewPlane, MeasuresDistancesFromTheOtherViewsPlane) {
  std::mt19937 rng(8);
  const std::vector<CrossViewPlane::Member> measured = OnPlane(&rng, 5, 0.0);
  const CrossViewPlane plane(measured, OnPlane(&rng, 40, 0.0));
  EXPECT_NEAR(std::abs(plane.normal().z()), 1.0, 1e-9);
  EXPECT_LT(plane.Residuals(Vector6d::Zero(), plane.normal(), 0.01).cwiseAbs().maxCoeff(), 1e-9);
  // Lifting one measured return by 3 cm is 3 sigma.
  std::vector<CrossViewPlane::Member> lifted = measured;
  lifted[2].p_lidar = lifted[2].T_world_lidar_corrected.inverse() *
                      (lifted[2].T_world_lidar_corrected * lifted[2].p_lidar + Eigen::Vector3d(0, 0, 0.03));
  const CrossViewPlane off(lifted, OnPlane(&rng, 40, 0.0));
  EXPECT_NEAR(std::abs(off.Residuals(Vector6d::Zero(), off.normal(), 0.01)(2)), 3.0, 1e-9);
  // Its noise information is zero for a noise-free plane.
  EXPECT_LT(plane.NormalNoiseInformation(0.01).norm(), 1e-12);
}

}  // namespace
}  // namespace unimap::calibration
