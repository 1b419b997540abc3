#include "matching/GaussianParticleFilter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "estimation/So3.hpp"
#include "matching/PoseRefiner.hpp"
#include "matching/ScanLikelihood.hpp"
#include "matching/VoxelDownsampler.hpp"

namespace unimap::matching {
namespace {

// Gauss-Newton steps of MatchFrom at least (it has no particles to start from).
constexpr int kMinRefineFromIterations = 5;

// The 6-D prior of the active dimensions' covariance S (unit variance elsewhere).
Matrix6d FullPrior(const Eigen::MatrixXd& S, const std::vector<int>& dims) {
  Matrix6d prior = Matrix6d::Identity();
  for (std::size_t r = 0; r < dims.size(); ++r) {
    for (std::size_t c = 0; c < dims.size(); ++c) {
      prior(dims[r], dims[c]) = S(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
    }
  }
  return prior;
}

// Dimensions sampled: all six, or x, y, yaw for planar motion.
std::vector<int> ActiveDims(bool planar) {
  return planar ? std::vector<int>{0, 1, 5} : std::vector<int>{0, 1, 2, 3, 4, 5};
}

// The body points in the map frame at T_map_body.
std::vector<Eigen::Vector3f> ToMap(const Eigen::Isometry3d& T_map_body, const std::vector<Eigen::Vector3f>& points) {
  const Eigen::Isometry3f T = T_map_body.cast<float>();
  std::vector<Eigen::Vector3f> points_map(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) points_map[i] = T * points[i];
  return points_map;
}

// Removes the points farther than max_distance_m + per_range * (the point's
// range) from the map at the predicted pose from *points; returns how many.
int DropUnseen(const Eigen::Isometry3d& T_map_body_predicted, const DistanceQuery& field, double max_distance_m,
               double per_range, std::vector<Eigen::Vector3f>* points) {
  const std::vector<Eigen::Vector3f> points_map = ToMap(T_map_body_predicted, *points);
  std::vector<float> distances(points->size());
  field.Distances(points_map.data(), static_cast<int>(points_map.size()), distances.data());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points->size(); ++i) {
    if (distances[i] <= max_distance_m + per_range * (*points)[i].norm()) (*points)[kept++] = (*points)[i];
  }
  const int dropped = static_cast<int>(points->size() - kept);
  points->resize(kept);
  return dropped;
}

// Moves the points whose cell at the predicted pose has a surface plane out
// of *points into plane points tied to that plane.
std::vector<PlanePoint> TieToPlanes(const Eigen::Isometry3d& T_map_body_predicted, const DistanceQuery& field,
                                    std::vector<Eigen::Vector3f>* points) {
  const int n = static_cast<int>(points->size());
  const std::vector<Eigen::Vector3f> points_map = ToMap(T_map_body_predicted, *points);
  std::unique_ptr<bool[]> has_plane(new bool[points->size()]);
  std::vector<Eigen::Vector3f> normals(points->size());
  std::vector<float> offsets(points->size());
  field.Planes(points_map.data(), n, has_plane.get(), normals.data(), offsets.data());
  std::vector<PlanePoint> plane_points;
  std::size_t kept = 0;
  for (int i = 0; i < n; ++i) {
    if (has_plane[i]) {
      plane_points.push_back(PlanePoint{(*points)[i], normals[i], offsets[i]});
    } else {
      (*points)[kept++] = (*points)[i];
    }
  }
  points->resize(kept);
  return plane_points;
}

}  // namespace

struct GaussianParticleFilter::Workspace {
  std::vector<Vector6d> particles;
  std::vector<Eigen::Isometry3d> poses;  // the particles applied to the prediction
  std::vector<double> log_weights;
  std::unique_ptr<tbb::task_arena> arena;
};

GaussianParticleFilter::GaussianParticleFilter(GpfOptions options)
    : options_(options), rng_(options.seed), workspace_(std::make_unique<Workspace>()) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("GpfOptions: " + why);
  if (options_.threads > 1) workspace_->arena = std::make_unique<tbb::task_arena>(options_.threads);
}

GaussianParticleFilter::~GaussianParticleFilter() = default;

GpfResult GaussianParticleFilter::Match(const Eigen::Isometry3d& T_map_body_predicted,
                                        const Matrix6d& predicted_covariance,
                                        const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                                        double max_predicted_distance_m, double max_predicted_distance_per_range) {
  return MatchImpl(T_map_body_predicted, predicted_covariance, points_body, field, max_predicted_distance_m,
                   max_predicted_distance_per_range, nullptr);
}

GpfResult GaussianParticleFilter::MatchFrom(const Eigen::Isometry3d& T_map_body_predicted,
                                            const Matrix6d& predicted_covariance,
                                            const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                                            double max_predicted_distance_m, const Vector6d& start,
                                            double max_predicted_distance_per_range) {
  return MatchImpl(T_map_body_predicted, predicted_covariance, points_body, field, max_predicted_distance_m,
                   max_predicted_distance_per_range, &start);
}

GpfResult GaussianParticleFilter::MatchImpl(const Eigen::Isometry3d& T_map_body_predicted,
                                            const Matrix6d& predicted_covariance,
                                            const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                                            double max_predicted_distance_m, double max_predicted_distance_per_range,
                                            const Vector6d* start) {
  GpfResult result;
  // Where the points are looked up before matching: the prediction, or the start given.
  const Eigen::Isometry3d T_map_body_gate =
      start != nullptr ? estimation::ApplyPoseError(T_map_body_predicted, *start) : T_map_body_predicted;
  const auto downsample_start = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector3f> points =
      VoxelDownsample(points_body, options_.voxel_size_m, options_.max_points, options_.seed + scans_matched_);
  result.downsample_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - downsample_start).count();
  ++scans_matched_;
  result.points_used = static_cast<int>(points.size());
  std::vector<PlanePoint> plane_points;
  if (options_.point_to_plane) plane_points = TieToPlanes(T_map_body_gate, field, &points);
  int unmeasured = 0;  // planes_only: the points left without a plane
  if (options_.planes_only) {
    unmeasured = static_cast<int>(points.size());
    points.clear();
  }
  if (max_predicted_distance_m > 0.0 && !points.empty()) {
    result.points_unseen =
        DropUnseen(T_map_body_gate, field, max_predicted_distance_m, max_predicted_distance_per_range, &points);
    unmeasured += result.points_unseen;
  }
  if (points.empty() && plane_points.empty()) {
    result.reason = result.points_unseen > 0 ? "no point near the map"
                    : unmeasured > 0         ? "no point has a plane"
                                             : "no points to match";
    return result;
  }
  const std::vector<int> dims = ActiveDims(options_.planar);
  const int d = static_cast<int>(dims.size());

  // Sampling covariance: the prediction on the active dimensions, floored.
  Eigen::MatrixXd S(d, d);
  for (int r = 0; r < d; ++r) {
    for (int c = 0; c < d; ++c) S(r, c) = predicted_covariance(dims[r], dims[c]);
  }
  for (int r = 0; r < d; ++r) {
    const double floor = dims[r] < 3 ? options_.min_sigma_position_m : options_.min_sigma_rotation_rad;
    S(r, r) = std::max(S(r, r), floor * floor);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success) {
    result.reason = "predicted covariance is not positive definite";
    return result;
  }
  const Eigen::MatrixXd L = llt.matrixL();
  if (start != nullptr)
    return RefineFrom(T_map_body_predicted, S, dims, *start, points, plane_points, field, unmeasured,
                      std::move(result));

  const int K = options_.num_particles;
  auto& ws = *workspace_;
  ws.particles.assign(static_cast<std::size_t>(K), Vector6d::Zero());
  ws.log_weights.assign(static_cast<std::size_t>(K), 0.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd xi(d);
  for (int k = 0; k < K; ++k) {
    for (int j = 0; j < d; ++j) xi(j) = normal(rng_);
    const Eigen::VectorXd e = L * xi;
    for (int j = 0; j < d; ++j) ws.particles[static_cast<std::size_t>(k)](dims[j]) = e(j);
  }

  // Weight every particle by the scan likelihood (independent, so parallel and deterministic).
  const ScanLikelihood likelihood(options_.point_sigma_m, options_.clamp_distance_m, options_.effective_points);
  ws.poses.resize(static_cast<std::size_t>(K));
  for (std::size_t i = 0; i < ws.poses.size(); ++i) {
    ws.poses[i] = estimation::ApplyPoseError(T_map_body_predicted, ws.particles[i]);
  }
  const auto weigh = [&](const tbb::blocked_range<int>& range) {
    likelihood.LogLikelihoods(field, ws.poses, range.begin(), range.end(), points, plane_points, unmeasured,
                              ws.log_weights.data());
  };
  if (ws.arena) {
    ws.arena->execute([&] { tbb::parallel_for(tbb::blocked_range<int>(0, K, 16), weigh); });
  } else {
    weigh(tbb::blocked_range<int>(0, K));
  }

  // Sample statistics (mu_s, S_s) and weighted posterior (mu_p, S_p).
  const double max_log = *std::max_element(ws.log_weights.begin(), ws.log_weights.end());
  std::vector<double> w(static_cast<std::size_t>(K));
  double sum_w = 0.0;
  for (int k = 0; k < K; ++k)
    sum_w += (w[static_cast<std::size_t>(k)] = std::exp(ws.log_weights[static_cast<std::size_t>(k)] - max_log));
  double sum_w2 = 0.0;
  for (auto& wk : w) {
    wk /= sum_w;
    sum_w2 += wk * wk;
  }
  result.effective_sample_size = 1.0 / sum_w2;
  Vector6d mu_s = Vector6d::Zero(), mu_p = Vector6d::Zero();
  for (int k = 0; k < K; ++k) {
    mu_s += ws.particles[static_cast<std::size_t>(k)] / K;
    mu_p += w[static_cast<std::size_t>(k)] * ws.particles[static_cast<std::size_t>(k)];
  }
  Matrix6d S_s = Matrix6d::Zero(), S_p = Matrix6d::Zero();
  for (int k = 0; k < K; ++k) {
    const Vector6d ds = ws.particles[static_cast<std::size_t>(k)] - mu_s;
    const Vector6d dp = ws.particles[static_cast<std::size_t>(k)] - mu_p;
    S_s += ds * ds.transpose() / (K - 1);
    S_p += w[static_cast<std::size_t>(k)] * dp * dp.transpose();
  }
  // Regularise the posterior by the particle spacing (kernel of S_s / K) so
  // a few dominant particles do not make it singular; unit variance in the
  // dimensions not sampled, so they carry no information.
  S_p += S_s / K;
  for (int i = 0; i < 6; ++i) {
    if (std::find(dims.begin(), dims.end(), i) == dims.end()) {
      S_s(i, i) = 1.0;
      S_p(i, i) = 1.0;
    }
  }
  result.sample_mean = mu_s;
  result.sample_covariance = S_s;
  result.posterior_mean = mu_p;
  result.posterior_covariance = S_p;
  if (options_.refine_iterations > 0) {
    // Refine on the analytic prior N(0, S) (not its sample estimate), from the GPF mean.
    ApplyRefinement(FullPrior(S, dims), dims,
                    RefineOnPosterior(T_map_body_predicted, FullPrior(S, dims), dims, mu_p, points, plane_points, field,
                                      unmeasured, options_.refine_iterations),
                    &result);
  }
  if (!result.refined) {
    result.measurement = RecoverPseudoMeasurement(mu_s, S_s, mu_p, S_p, options_.min_information_ratio);
  }
  if (!result.measurement.ok) {
    result.reason = "sample or posterior covariance is not positive definite";
    return result;
  }
  result.ok = true;
  return result;
}

PoseRefinement GaussianParticleFilter::RefineOnPosterior(
    const Eigen::Isometry3d& T_map_body_predicted, const Matrix6d& prior, const std::vector<int>& dims,
    const Vector6d& start, const std::vector<Eigen::Vector3f>& points, const std::vector<PlanePoint>& plane_points,
    const DistanceQuery& field, int unmeasured, int iterations) const {
  const PoseRefiner refiner(options_.point_sigma_m, options_.clamp_distance_m, options_.effective_points, iterations);
  return refiner.Refine(T_map_body_predicted, Vector6d::Zero(), prior, start, dims, points, plane_points, field,
                        unmeasured);
}

void GaussianParticleFilter::ApplyRefinement(const Matrix6d& prior, const std::vector<int>& /*dims*/,
                                             const PoseRefinement& refined, GpfResult* result) const {
  if (!refined.ok) return;
  result->refined = true;
  result->refine_iterations = refined.iterations;
  result->posterior_mean = refined.mean;
  result->posterior_covariance = refined.covariance;
  result->measurement = RecoverPseudoMeasurement(Vector6d::Zero(), prior, refined.mean, refined.covariance,
                                                 options_.min_information_ratio);
}

GpfResult GaussianParticleFilter::RefineFrom(const Eigen::Isometry3d& T_map_body_predicted, const Eigen::MatrixXd& S,
                                             const std::vector<int>& dims, const Vector6d& start,
                                             const std::vector<Eigen::Vector3f>& points,
                                             const std::vector<PlanePoint>& plane_points, const DistanceQuery& field,
                                             int unmeasured, GpfResult result) const {
  const Matrix6d prior = FullPrior(S, dims);
  result.sample_mean = Vector6d::Zero();
  result.sample_covariance = prior;
  ApplyRefinement(prior, dims,
                  RefineOnPosterior(T_map_body_predicted, prior, dims, start, points, plane_points, field, unmeasured,
                                    std::max(options_.refine_iterations, kMinRefineFromIterations)),
                  &result);
  if (!result.refined) {
    result.reason = "refinement from the start given failed";
    return result;
  }
  if (!result.measurement.ok) {
    result.reason = "posterior covariance is not positive definite";
    return result;
  }
  result.ok = true;
  return result;
}

}  // namespace unimap::matching
