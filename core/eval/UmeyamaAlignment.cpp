#include "eval/UmeyamaAlignment.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

// The point sets as 3 x n matrices (Eigen::umeyama's input); throws
// InputError unless they are equally many and not empty.
void ToMatrices(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                Eigen::Matrix3Xd* s, Eigen::Matrix3Xd* t) {
  if (source.empty() || source.size() != target.size()) {
    throw InputError("alignment needs equally many (>= 1) source and target points, got " +
                     std::to_string(source.size()) + " and " + std::to_string(target.size()));
  }
  s->resize(3, static_cast<Eigen::Index>(source.size()));
  t->resize(3, static_cast<Eigen::Index>(target.size()));
  for (std::size_t i = 0; i < source.size(); ++i) {
    s->col(static_cast<Eigen::Index>(i)) = source[i];
    t->col(static_cast<Eigen::Index>(i)) = target[i];
  }
}

double Rmse(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, const Eigen::Isometry3d& T, double scale) {
  const Eigen::Matrix3Xd mapped = (scale * T.linear() * source).colwise() + T.translation();
  return std::sqrt((mapped - target).colwise().squaredNorm().mean());
}

}  // namespace

RigidAlignment AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  Eigen::Matrix3Xd s;
  Eigen::Matrix3Xd t;
  ToMatrices(source, target, &s, &t);
  // Umeyama (1991) eqs. 34-41 with c = 1.
  const Eigen::Matrix4d T = Eigen::umeyama(s, t, false);
  RigidAlignment result;
  result.T_target_source.linear() = T.topLeftCorner<3, 3>();
  result.T_target_source.translation() = T.topRightCorner<3, 1>();
  result.rmse_m = Rmse(s, t, result.T_target_source, 1.0);
  return result;
}

std::optional<SimilarityAlignment> AlignSimilarity(const std::vector<Eigen::Vector3d>& source,
                                                   const std::vector<Eigen::Vector3d>& target) {
  Eigen::Matrix3Xd s;
  Eigen::Matrix3Xd t;
  ToMatrices(source, target, &s, &t);
  // Eq. 42's scale c = tr(D S) / sigma_s^2 needs a source that does not all coincide.
  const double source_variance = (s.colwise() - s.rowwise().mean()).colwise().squaredNorm().mean();
  if (!(source_variance > 0.0)) return std::nullopt;
  const Eigen::Matrix4d T = Eigen::umeyama(s, t, true);  // eqs. 34-42
  // c R is the top-left block; det(R) = 1, so c = cbrt(det(c R)).
  const Eigen::Matrix3d cR = T.topLeftCorner<3, 3>();
  const double scale = std::cbrt(cR.determinant());
  if (!(scale > 0.0) || !std::isfinite(scale)) return std::nullopt;
  SimilarityAlignment result;
  result.scale = scale;
  result.T_target_source.linear() = cR / scale;
  result.T_target_source.translation() = T.topRightCorner<3, 1>();
  result.rmse_m = Rmse(s, t, result.T_target_source, scale);
  return result;
}

}  // namespace unimap::eval
