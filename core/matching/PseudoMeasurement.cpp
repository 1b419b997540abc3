#include "matching/PseudoMeasurement.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace unimap::matching {

PseudoMeasurement RecoverPseudoMeasurement(const Vector6d& mu_s, const Matrix6d& S_s, const Vector6d& mu_p,
                                           const Matrix6d& S_p, double min_information_ratio) {
  PseudoMeasurement out;
  const Eigen::LLT<Matrix6d> llt_s(S_s);
  const Eigen::LLT<Matrix6d> llt_p(S_p);
  if (llt_s.info() != Eigen::Success || llt_p.info() != Eigen::Success) return out;
  const Matrix6d I = Matrix6d::Identity();
  const Matrix6d info_s = llt_s.solve(I);
  const Matrix6d info_p = llt_p.solve(I);
  // Information the scan added: R^-1 = S_p^-1 - S_s^-1, repaired to be positive definite.
  Matrix6d gain = info_p - info_s;
  gain = 0.5 * (gain + gain.transpose());
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(gain);
  Vector6d values = eig.eigenvalues();
  const double floor = std::max(values.maxCoeff(), 0.0) * min_information_ratio;
  const double safe_floor = floor > 0.0 ? floor : 1e-12;
  for (int i = 0; i < 6; ++i) {
    if (values(i) < safe_floor) {
      values(i) = safe_floor;
      ++out.repaired_eigenvalues;
    }
  }
  const Matrix6d& V = eig.eigenvectors();
  out.R = V * values.cwiseInverse().asDiagonal() * V.transpose();
  out.R = 0.5 * (out.R + out.R.transpose());
  // K^-1 = (S_s + R) S_s^-1 = I + R S_s^-1
  const Matrix6d K_inv = I + out.R * info_s;
  out.z = K_inv * (mu_p - mu_s) + mu_s;
  out.ok = true;
  return out;
}

}  // namespace unimap::matching
