#include "graph/LoopClosureRefiner.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "estimation/So3.hpp"

namespace unimap::graph {

namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// Huber's rho(d) with threshold delta.
double Huber(double d, double delta) { return d <= delta ? 0.5 * d * d : delta * (d - 0.5 * delta); }

// Residual of one point x = R p + t against the nearest submap point q of
// its cell: point-to-plane n . (x - q) when q has a normal (*planar), else
// the point-to-point |x - q|; J its Jacobian in [dp, dtheta]. False when no
// submap point lies near x.
bool PointResidual(const LoopClosureDistanceField& field, const Eigen::Matrix3d& R, const Eigen::Vector3f& x,
                   const Eigen::Vector3f& p, double* r, Vector6d* J, bool* planar) {
  Eigen::Vector3f q;
  Eigen::Vector3f n;
  if (!field.NearestPoint(x, &q, &n)) return false;
  const Eigen::Vector3d diff = (x - q).cast<double>();
  Eigen::Vector3d g = n.cast<double>();
  *planar = n.squaredNorm() > 0.0f;
  if (*planar) {
    *r = g.dot(diff);
  } else {
    *r = diff.norm();
    g = *r > 1e-9 ? Eigen::Vector3d(diff / *r) : Eigen::Vector3d::Zero();
  }
  J->head<3>() = g;
  J->tail<3>() = p.cast<double>().cross(R.transpose() * g);
  return true;
}

// One pass over the points at T: the truncated Huber cost (a point with no
// submap point near counts as the clamp distance) and the normal equations
// of the reweighted least squares (Huber weights w = min(1, delta / |r|)):
// H = sum w J^T J, b = sum w r J^T. Returns the number of points with weight.
int Linearise(const LoopClosureDistanceField& field, const std::vector<Eigen::Vector3f>& points,
              const Eigen::Isometry3d& T, double delta, double* cost, Matrix6d* H, Vector6d* b) {
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Matrix3f Rf = R.cast<float>();
  const Eigen::Vector3f t = T.translation().cast<float>();
  const double outlier_cost = Huber(field.clamp(), delta);
  *cost = 0.0;
  H->setZero();
  b->setZero();
  int used = 0;
  for (const Eigen::Vector3f& p : points) {
    double r = 0.0;
    Vector6d J;
    bool planar = false;
    if (!PointResidual(field, R, Rf * p + t, p, &r, &J, &planar)) {
      *cost += outlier_cost;
      continue;
    }
    const double magnitude = std::abs(r);
    *cost += std::min(outlier_cost, Huber(magnitude, delta));
    const double w = magnitude <= delta ? 1.0 : delta / magnitude;
    H->selfadjointView<Eigen::Upper>().rankUpdate(J, w);
    *b += (w * r) * J;
    ++used;
  }
  *H = H->selfadjointView<Eigen::Upper>();
  return used;
}

}  // namespace

LoopClosureRefiner::LoopClosureRefiner(const LoopClosureDistanceField& field, const LoopClosureOptions& options)
    : field_(field), options_(options) {}

double LoopClosureRefiner::Score(const std::vector<Eigen::Vector3f>& points_body,
                                 const Eigen::Isometry3d& T_submap_body) const {
  if (points_body.empty()) return 0.0;
  const Eigen::Matrix3f R = T_submap_body.linear().cast<float>();
  const Eigen::Vector3f t = T_submap_body.translation().cast<float>();
  int inliers = 0;
  for (const Eigen::Vector3f& p : points_body) {
    if (field_.Distance(R * p + t, nullptr) <= options_.inlier_distance_m) ++inliers;
  }
  return static_cast<double>(inliers) / static_cast<double>(points_body.size());
}

LoopClosureRefinement LoopClosureRefiner::Refine(const std::vector<Eigen::Vector3f>& points_body,
                                                 const Eigen::Isometry3d& T_initial, int max_iterations) const {
  LoopClosureRefinement out;
  out.T_submap_body = T_initial;
  const double delta = options_.huber_m;
  Eigen::Isometry3d T = T_initial;
  double cost = 0.0;
  Matrix6d H;
  Vector6d b;
  if (Linearise(field_, points_body, T, delta, &cost, &H, &b) < 6) {
    out.reason = "fewer than 6 scan points near the submap surface";
    return out;
  }
  double lambda = 1e-3;
  Matrix6d candidate_H;
  Vector6d candidate_b;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    out.iterations = iteration + 1;
    Matrix6d A = H;
    A.diagonal() = A.diagonal() * (1.0 + lambda) + Vector6d::Constant(1e-9);
    const Vector6d step = A.ldlt().solve(-b);
    const Eigen::Isometry3d candidate = estimation::ApplyPoseError(T, step);
    double candidate_cost = 0.0;
    const int used = Linearise(field_, points_body, candidate, delta, &candidate_cost, &candidate_H, &candidate_b);
    if (candidate_cost < cost && used >= 6) {
      const double decrease = (cost - candidate_cost) / cost;
      T = candidate;
      cost = candidate_cost;
      H = candidate_H;
      b = candidate_b;
      lambda = std::max(1e-7, lambda * 0.3);
      if (decrease < 1e-4 || (step.head<3>().norm() < 1e-4 && step.tail<3>().norm() < 1e-5)) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e6) break;  // no descent left
    }
  }
  out.ok = true;
  out.T_submap_body = T;

  // Inliers, their spread and the Gauss-Newton information.
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Matrix3f Rf = R.cast<float>();
  const Eigen::Vector3f t = T.translation().cast<float>();
  Matrix6d information = Matrix6d::Zero();
  double sum2 = 0.0;
  int planar_inliers = 0;
  out.inlier_mask.assign(points_body.size(), 0);
  for (std::size_t i = 0; i < points_body.size(); ++i) {
    const Eigen::Vector3f& p = points_body[i];
    const Eigen::Vector3f x = Rf * p + t;
    if (field_.Distance(x, nullptr) > options_.inlier_distance_m) continue;
    out.inlier_mask[i] = 1;
    ++out.inliers;
    double r = 0.0;
    Vector6d J;
    bool planar = false;
    // Only plane residuals inform the covariance: point-to-point ones along
    // edges would constrain the edge direction by the sampling ripple.
    if (!PointResidual(field_, R, x, p, &r, &J, &planar) || !planar) continue;
    information.selfadjointView<Eigen::Upper>().rankUpdate(J, 1.0);
    sum2 += r * r;
    ++planar_inliers;
  }
  information = information.selfadjointView<Eigen::Upper>();
  out.score = points_body.empty() ? 0.0 : static_cast<double>(out.inliers) / static_cast<double>(points_body.size());
  out.rms_m = planar_inliers > 0 ? std::sqrt(sum2 / planar_inliers) : 0.0;

  Vector6d floor;
  floor << Eigen::Vector3d::Constant(options_.min_sigma_position_m * options_.min_sigma_position_m),
      Eigen::Vector3d::Constant(options_.min_sigma_rotation_rad * options_.min_sigma_rotation_rad);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(information);
  const double largest = eigen.eigenvalues().maxCoeff();
  if (planar_inliers <= 6 || !(largest > 0.0)) {
    out.covariance = Matrix6d::Identity() * 1e6;  // unconstrained
    return out;
  }
  const double sigma = std::max(std::sqrt(sum2 / (planar_inliers - 6)), options_.inlier_distance_m / 10.0);
  const double inflation = std::max(1.0, planar_inliers / options_.effective_points);
  const Vector6d inverse_eigen = eigen.eigenvalues().cwiseMax(1e-12 * largest).cwiseInverse();
  Matrix6d covariance = eigen.eigenvectors() * inverse_eigen.asDiagonal() * eigen.eigenvectors().transpose();
  covariance *= sigma * sigma * inflation;
  covariance.diagonal() += floor;
  out.covariance = 0.5 * (covariance + covariance.transpose());
  return out;
}

}  // namespace unimap::graph
