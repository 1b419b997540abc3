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

}  // namespace unimap::matching
