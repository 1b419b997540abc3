#include "eval/UmeyamaAlignment.hpp"

#include <cmath>
#include <string>

#include <Eigen/SVD>

#include "unimap/Errors.hpp"

namespace unimap::eval {

RigidAlignment AlignRigid(const std::vector<Eigen::Vector3d>& source,
                          const std::vector<Eigen::Vector3d>& target) {
  if (source.empty() || source.size() != target.size()) {
    throw InputError("rigid alignment needs equally many (>= 1) source and target points, got " +
                     std::to_string(source.size()) + " and " + std::to_string(target.size()));
  }
  const double n = static_cast<double>(source.size());
  // Umeyama (1991) eqs. 34-35: centroids mu_s, mu_t.
  Eigen::Vector3d mu_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d mu_t = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) {
    mu_s += source[i];
    mu_t += target[i];
  }
  mu_s /= n;
  mu_t /= n;
  // Eq. 38: cross-covariance Sigma = 1/n sum (t_i - mu_t)(s_i - mu_s)^T.
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) {
    sigma += (target[i] - mu_t) * (source[i] - mu_s).transpose();
  }
  sigma /= n;
  // Eqs. 39-40: Sigma = U D V^T, R = U S V^T with S = diag(1, 1, det(U) det(V)).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  RigidAlignment result;
  result.T_target_source.linear() = svd.matrixU() * S * svd.matrixV().transpose();
  // Eq. 41 with c = 1: t = mu_t - R mu_s.
  result.T_target_source.translation() = mu_t - result.T_target_source.linear() * mu_s;
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    sum_sq += (result.T_target_source * source[i] - target[i]).squaredNorm();
  }
  result.rmse_m = std::sqrt(sum_sq / n);
  return result;
}

}  // namespace unimap::eval
