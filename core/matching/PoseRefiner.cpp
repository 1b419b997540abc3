#include "matching/PoseRefiner.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Cholesky>

#include "estimation/So3.hpp"

namespace unimap::matching {
namespace {

// Scratch for one evaluation: transformed points, distances, gradients.
struct Scratch {
  std::vector<Eigen::Vector3f> points_map;
  std::vector<float> distances;
  std::vector<Eigen::Vector3f> gradients;
};

void Transform(const Eigen::Isometry3d& T, const std::vector<Eigen::Vector3f>& points_body, Scratch* s) {
  const Eigen::Matrix3f R = T.linear().cast<float>();
  const Eigen::Vector3f t = T.translation().cast<float>();
  s->points_map.resize(points_body.size());
  for (std::size_t i = 0; i < points_body.size(); ++i) s->points_map[i] = R * points_body[i] + t;
  s->distances.resize(points_body.size());
}

}  // namespace

PoseRefiner::PoseRefiner(double sigma_m, double clamp_m, double effective_points, int max_iterations)
    : sigma_m_(sigma_m), clamp_m_(clamp_m), effective_points_(effective_points), max_iterations_(max_iterations) {
  assert(sigma_m > 0.0 && clamp_m > 0.0 && effective_points > 0.0 && max_iterations >= 1);
}

PoseRefinement PoseRefiner::Refine(const Eigen::Isometry3d& T_map_body_predicted, const Vector6d& prior_mean,
                                   const Matrix6d& prior_covariance, const Vector6d& start,
                                   const std::vector<int>& active_dims, const std::vector<Eigen::Vector3f>& points_body,
                                   const DistanceQuery& field) const {
  return Refine(T_map_body_predicted, prior_mean, prior_covariance, start, active_dims, points_body, {}, field);
}

PoseRefinement PoseRefiner::Refine(const Eigen::Isometry3d& T_map_body_predicted, const Vector6d& prior_mean,
                                   const Matrix6d& prior_covariance, const Vector6d& start,
                                   const std::vector<int>& active_dims, const std::vector<Eigen::Vector3f>& points_body,
                                   const std::vector<PlanePoint>& plane_points, const DistanceQuery& field,
                                   int unmeasured_points) const {
  PoseRefinement out;
  const int n = static_cast<int>(points_body.size());
  const int measured = n + static_cast<int>(plane_points.size());
  const int d = static_cast<int>(active_dims.size());
  if (measured == 0 || d == 0) {
    out.reason = measured == 0 ? "no points to match" : "no active dimension";
    return out;
  }
  const int total = measured + unmeasured_points;
  // Prior information on the active dimensions.
  Eigen::MatrixXd P(d, d);
  for (int r = 0; r < d; ++r) {
    for (int c = 0; c < d; ++c) P(r, c) = prior_covariance(active_dims[r], active_dims[c]);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt_prior(P);
  if (llt_prior.info() != Eigen::Success) {
    out.reason = "prior covariance is not positive definite";
    return out;
  }
  const Eigen::MatrixXd P_inv = llt_prior.solve(Eigen::MatrixXd::Identity(d, d));
  const double w = effective_points_ / (static_cast<double>(total) * sigma_m_ * sigma_m_);  // W
  const auto clamp = static_cast<float>(clamp_m_);
  const auto active = [&](const Vector6d& e) {
    Eigen::VectorXd v(d);
    for (int r = 0; r < d; ++r) v(r) = e(active_dims[r]);
    return v;
  };
  const auto prior_cost = [&](const Vector6d& e) {
    const Eigen::VectorXd r = active(e - prior_mean);
    return 0.5 * r.dot(P_inv * r);
  };
  Scratch s;
  const auto cost = [&](const Vector6d& e) {
    const Eigen::Isometry3d T = estimation::ApplyPoseError(T_map_body_predicted, e);
    Transform(T, points_body, &s);
    field.Distances(s.points_map.data(), n, s.distances.data());
    double sum_sq = 0.0;
    for (int i = 0; i < n; ++i) {
      const double di = std::min(s.distances[static_cast<std::size_t>(i)], clamp);
      sum_sq += di * di;
    }
    const Eigen::Isometry3f Tf = T.cast<float>();
    for (const PlanePoint& q : plane_points) {
      const double di = std::min(std::abs(q.SignedDistance(Tf * q.p_body)), clamp);
      sum_sq += di * di;
    }
    return prior_cost(e) + 0.5 * w * sum_sq;
  };
  // Gauss-Newton system (full 6-D) at e: H = J' W J, g = J' W d; returns the cost.
  const auto linearise = [&](const Vector6d& e, Matrix6d* H, Vector6d* g) {
    const Eigen::Isometry3d T = estimation::ApplyPoseError(T_map_body_predicted, e);
    Transform(T, points_body, &s);
    s.gradients.resize(points_body.size());
    field.DistancesAndGradients(s.points_map.data(), n, s.distances.data(), s.gradients.data());
    const Eigen::Matrix3d Rt = T.linear().transpose();
    H->setZero();
    g->setZero();
    double sum_sq = 0.0;
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double di = s.distances[k];
      if (!(di < clamp_m_)) {
        sum_sq += clamp_m_ * clamp_m_;
        continue;
      }
      sum_sq += di * di;
      const Eigen::Vector3d grad = s.gradients[k].cast<double>();
      Vector6d J;
      J.head<3>() = grad;
      J.tail<3>() = points_body[k].cast<double>().cross(Rt * grad);
      H->noalias() += J * J.transpose();
      *g += di * J;
    }
    // Plane points: signed residual r = n . (R p + t) + o, gradient n.
    const Eigen::Isometry3f Tf = T.cast<float>();
    for (const PlanePoint& q : plane_points) {
      const double ri = q.SignedDistance(Tf * q.p_body);
      if (!(std::abs(ri) < clamp_m_)) {
        sum_sq += clamp_m_ * clamp_m_;
        continue;
      }
      sum_sq += ri * ri;
      const Eigen::Vector3d normal = q.normal_map.cast<double>();
      Vector6d J;
      J.head<3>() = normal;
      J.tail<3>() = q.p_body.cast<double>().cross(Rt * normal);
      H->noalias() += J * J.transpose();
      *g += ri * J;
    }
    *H *= w;
    *g *= w;
    return prior_cost(e) + 0.5 * w * sum_sq;
  };

  Vector6d e = start;
  Matrix6d H;
  Vector6d g;
  double current = linearise(e, &H, &g);
  out.initial_cost = current;
  for (int it = 0; it < max_iterations_; ++it) {
    Eigen::MatrixXd A(d, d);
    Eigen::VectorXd b(d);
    for (int r = 0; r < d; ++r) {
      for (int c = 0; c < d; ++c) A(r, c) = H(active_dims[r], active_dims[c]);
      b(r) = g(active_dims[r]);
    }
    A += P_inv;
    b += P_inv * active(e - prior_mean);
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
    if (ldlt.info() != Eigen::Success) break;
    const Eigen::VectorXd step = -ldlt.solve(b);
    bool accepted = false;
    for (double scale = 1.0; scale >= 0.25 && !accepted; scale *= 0.5) {
      Vector6d candidate = e;
      for (int r = 0; r < d; ++r) candidate(active_dims[r]) += scale * step(r);
      const double c = cost(candidate);
      if (c < current) {
        e = candidate;
        accepted = true;
      }
    }
    if (!accepted) break;
    ++out.iterations;
    current = linearise(e, &H, &g);
    if (step.norm() < 1e-6) break;
  }
  out.final_cost = current;
  out.mean = e;
  // Laplace posterior on the active dimensions; the others keep the prior
  // (the scan told nothing there).
  Eigen::MatrixXd A(d, d);
  for (int r = 0; r < d; ++r) {
    for (int c = 0; c < d; ++c) A(r, c) = H(active_dims[r], active_dims[c]);
  }
  A += P_inv;
  const Eigen::LLT<Eigen::MatrixXd> llt_post(A);
  if (llt_post.info() != Eigen::Success) {
    out.reason = "posterior information is not positive definite";
    return out;
  }
  const Eigen::MatrixXd C = llt_post.solve(Eigen::MatrixXd::Identity(d, d));
  // Inactive dimensions keep their prior variances, uncorrelated with the rest.
  for (int i = 0; i < 6; ++i) out.covariance(i, i) = prior_covariance(i, i);
  for (int r = 0; r < d; ++r) {
    for (int c = 0; c < d; ++c) {
      out.covariance(active_dims[r], active_dims[c]) = C(r, c);
      out.information(active_dims[r], active_dims[c]) = H(active_dims[r], active_dims[c]);
    }
  }
  out.ok = true;
  return out;
}

}  // namespace unimap::matching
