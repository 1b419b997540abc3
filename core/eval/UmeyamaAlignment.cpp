#include "eval/UmeyamaAlignment.hpp"

#include <cmath>
#include <string>

#include <Eigen/SVD>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

// The parts of Umeyama's solution shared by the rigid and the similarity fit.
struct Umeyama {
  Eigen::Vector3d mu_s = Eigen::Vector3d::Zero();  // source centroid
  Eigen::Vector3d mu_t = Eigen::Vector3d::Zero();  // target centroid
  double var_s = 0.0;                              // sigma_s^2 = 1/n sum |s_i - mu_s|^2
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // the optimal rotation
  double trace_DS = 0.0;                           // tr(D S), numerator of the scale
};

Umeyama Solve(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  if (source.empty() || source.size() != target.size()) {
    throw InputError("alignment needs equally many (>= 1) source and target points, got " +
                     std::to_string(source.size()) + " and " + std::to_string(target.size()));
  }
  const double n = static_cast<double>(source.size());
  Umeyama u;
  // Umeyama (1991) eqs. 34-35: centroids mu_s, mu_t; eq. 36: variance sigma_s^2.
  for (std::size_t i = 0; i < source.size(); ++i) {
    u.mu_s += source[i];
    u.mu_t += target[i];
  }
  u.mu_s /= n;
  u.mu_t /= n;
  // Eq. 38: cross-covariance Sigma = 1/n sum (t_i - mu_t)(s_i - mu_s)^T.
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) {
    sigma += (target[i] - u.mu_t) * (source[i] - u.mu_s).transpose();
    u.var_s += (source[i] - u.mu_s).squaredNorm();
  }
  sigma /= n;
  u.var_s /= n;
  // Eqs. 39-40: Sigma = U D V^T, R = U S V^T with S = diag(1, 1, det(U) det(V)).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  u.R = svd.matrixU() * S * svd.matrixV().transpose();
  u.trace_DS = svd.singularValues().dot(S.diagonal());
  return u;
}

double Rmse(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
            const Eigen::Isometry3d& T, double scale) {
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    sum_sq += (scale * (T.linear() * source[i]) + T.translation() - target[i]).squaredNorm();
  }
  return std::sqrt(sum_sq / static_cast<double>(source.size()));
}

}  // namespace

RigidAlignment AlignRigid(const std::vector<Eigen::Vector3d>& source,
                          const std::vector<Eigen::Vector3d>& target) {
  const Umeyama u = Solve(source, target);
  RigidAlignment result;
  result.T_target_source.linear() = u.R;
  // Eq. 41 with c = 1: t = mu_t - R mu_s.
  result.T_target_source.translation() = u.mu_t - u.R * u.mu_s;
  result.rmse_m = Rmse(source, target, result.T_target_source, 1.0);
  return result;
}

std::optional<SimilarityAlignment> AlignSimilarity(const std::vector<Eigen::Vector3d>& source,
                                                   const std::vector<Eigen::Vector3d>& target) {
  const Umeyama u = Solve(source, target);
  // Eq. 42: c = tr(D S) / sigma_s^2.
  if (!(u.var_s > 0.0)) return std::nullopt;
  const double scale = u.trace_DS / u.var_s;
  if (!(scale > 0.0) || !std::isfinite(scale)) return std::nullopt;
  SimilarityAlignment result;
  result.scale = scale;
  result.T_target_source.linear() = u.R;
  // Eq. 41: t = mu_t - c R mu_s.
  result.T_target_source.translation() = u.mu_t - scale * (u.R * u.mu_s);
  result.rmse_m = Rmse(source, target, result.T_target_source, scale);
  return result;
}

}  // namespace unimap::eval
