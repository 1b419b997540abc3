#include "matching/ScanLikelihood.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::matching {

ScanLikelihood::ScanLikelihood(double sigma_m, double clamp_m, double effective_points)
    : inv_two_sigma_sq_(static_cast<float>(1.0 / (2.0 * sigma_m * sigma_m))),
      clamp_m_(static_cast<float>(clamp_m)),
      effective_points_(effective_points) {}

double ScanLikelihood::LogLikelihood(const DistanceQuery& field, const Eigen::Isometry3d& T_map_body,
                                     const std::vector<Eigen::Vector3f>& points_body,
                                     std::vector<Eigen::Vector3f>* scratch_points,
                                     std::vector<float>* scratch_distances) const {
  return LogLikelihood(field, T_map_body, points_body, {}, scratch_points, scratch_distances);
}

double ScanLikelihood::LogLikelihood(const DistanceQuery& field, const Eigen::Isometry3d& T_map_body,
                                     const std::vector<Eigen::Vector3f>& points_body,
                                     const std::vector<PlanePoint>& plane_points,
                                     std::vector<Eigen::Vector3f>* scratch_points,
                                     std::vector<float>* scratch_distances, int unmeasured_points) const {
  const int n = static_cast<int>(points_body.size());
  const int measured = n + static_cast<int>(plane_points.size());
  if (measured == 0) return 0.0;
  const int total = measured + unmeasured_points;
  scratch_points->resize(points_body.size());
  scratch_distances->resize(points_body.size());
  const Eigen::Matrix3f R = T_map_body.linear().cast<float>();
  const Eigen::Vector3f t = T_map_body.translation().cast<float>();
  for (int i = 0; i < n; ++i) (*scratch_points)[i] = R * points_body[i] + t;
  field.Distances(scratch_points->data(), n, scratch_distances->data());
  float sum_sq = 0.0f;
  for (int i = 0; i < n; ++i) {
    const float d = std::min((*scratch_distances)[i], clamp_m_);
    sum_sq += d * d;
  }
  for (const PlanePoint& q : plane_points) {
    const float d = std::min(std::abs(q.SignedDistance(R * q.p_body + t)), clamp_m_);
    sum_sq += d * d;
  }
  return -static_cast<double>(sum_sq * inv_two_sigma_sq_) * effective_points_ / total;
}

void ScanLikelihood::LogLikelihoods(const DistanceQuery& field, const std::vector<Eigen::Isometry3d>& poses, int first,
                                    int last, const std::vector<Eigen::Vector3f>& points_body,
                                    const std::vector<PlanePoint>& plane_points, int unmeasured_points,
                                    double* log_likelihoods) const {
  const int count = last - first;
  if (count <= 0) return;
  const int measured = static_cast<int>(points_body.size() + plane_points.size());
  if (measured == 0) {
    for (int k = first; k < last; ++k) log_likelihoods[k] = 0.0;
    return;
  }
  const std::size_t m = static_cast<std::size_t>(count);
  std::vector<Eigen::Matrix3f> rotations(m);
  std::vector<Eigen::Vector3f> translations(m);
  for (std::size_t k = 0; k < m; ++k) {
    rotations[k] = poses[static_cast<std::size_t>(first) + k].linear().cast<float>();
    translations[k] = poses[static_cast<std::size_t>(first) + k].translation().cast<float>();
  }
  std::vector<float> sum_sq(m, 0.0f);
  std::vector<Eigen::Vector3f> transformed(m);
  std::vector<float> distances(m);
  for (const Eigen::Vector3f& p : points_body) {
    for (std::size_t k = 0; k < m; ++k) transformed[k] = rotations[k] * p + translations[k];
    field.Distances(transformed.data(), count, distances.data());
    for (std::size_t k = 0; k < m; ++k) {
      const float d = std::min(distances[k], clamp_m_);
      sum_sq[k] += d * d;
    }
  }
  for (const PlanePoint& q : plane_points) {
    for (std::size_t k = 0; k < m; ++k) {
      const float d = std::min(std::abs(q.SignedDistance(rotations[k] * q.p_body + translations[k])), clamp_m_);
      sum_sq[k] += d * d;
    }
  }
  const int total = measured + unmeasured_points;
  for (std::size_t k = 0; k < m; ++k) {
    log_likelihoods[static_cast<std::size_t>(first) + k] =
        -static_cast<double>(sum_sq[k] * inv_two_sigma_sq_) * effective_points_ / total;
  }
}

}  // namespace unimap::matching
