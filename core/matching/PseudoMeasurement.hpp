#pragma once
#include <Eigen/Core>

namespace unimap::matching {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// A pose measurement in error coordinates [dp, dtheta] for the ESKF.
struct PseudoMeasurement {
  bool ok = false;                    // false: a covariance was not positive definite
  Vector6d z = Vector6d::Zero();      // measured pose error
  Matrix6d R = Matrix6d::Identity();  // its covariance
  int repaired_eigenvalues = 0;       // information eigenvalues raised to the floor
};

// Recovers the measurement that, fed to a Kalman update whose prior is the
// sample prior N(mu_s, S_s), yields the posterior N(mu_p, S_p) (docs/design.md 1.3):
//   R = (S_p^-1 - S_s^-1)^-1,  K = S_s (S_s + R)^-1,  z = K^-1 (mu_p - mu_s) + mu_s.
// Non-positive eigenvalues of the information gain S_p^-1 - S_s^-1 (the scan
// told nothing in that direction) are raised to min_information_ratio times
// the largest one, so R stays finite and positive definite.
PseudoMeasurement RecoverPseudoMeasurement(const Vector6d& mu_s, const Matrix6d& S_s, const Vector6d& mu_p,
                                           const Matrix6d& S_p, double min_information_ratio);

}  // namespace unimap::matching
