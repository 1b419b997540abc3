#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "matching/DistanceQuery.hpp"
#include "matching/PlanePoint.hpp"

namespace unimap::matching {

// Log-likelihood of a scan at a pose in a distance map (the GPF's weight):
//   log L = (effective_points / n) * sum_i -min(d_i, clamp)^2 / (2 sigma^2),
// d_i the distance of point i, transformed by T_map_body, to the nearest
// surface (for points tied to a plane, PlanePoint, to that plane). Scaling
// to effective_points treats neighbouring returns as correlated so that one
// scan does not make the weights degenerate.
class ScanLikelihood {
 public:
  ScanLikelihood(double sigma_m, double clamp_m, double effective_points);

  // Scratch buffers are resized as needed (one set per thread).
  double LogLikelihood(const DistanceQuery& field, const Eigen::Isometry3d& T_map_body,
                       const std::vector<Eigen::Vector3f>& points_body, std::vector<Eigen::Vector3f>* scratch_points,
                       std::vector<float>* scratch_distances) const;
  // The same over the points measured in the field and those tied to planes;
  // n counts both and unmeasured_points, scan points that carry no
  // measurement (without a plane under GpfOptions::planes_only, or too far
  // from the map at the prediction: GaussianParticleFilter::Match), so a
  // scan whose points are mostly unmeasurable weighs less.
  double LogLikelihood(const DistanceQuery& field, const Eigen::Isometry3d& T_map_body,
                       const std::vector<Eigen::Vector3f>& points_body, const std::vector<PlanePoint>& plane_points,
                       std::vector<Eigen::Vector3f>* scratch_points, std::vector<float>* scratch_distances,
                       int unmeasured_points = 0) const;

  // The same for every pose of poses[first, last), written to
  // log_likelihoods[first, last). Point by point across the poses: the
  // poses are near each other (particles), so the lookups of one point hit
  // the same few field blocks.
  void LogLikelihoods(const DistanceQuery& field, const std::vector<Eigen::Isometry3d>& poses, int first, int last,
                      const std::vector<Eigen::Vector3f>& points_body, const std::vector<PlanePoint>& plane_points,
                      int unmeasured_points, double* log_likelihoods) const;

 private:
  float inv_two_sigma_sq_;
  float clamp_m_;
  double effective_points_;
};

}  // namespace unimap::matching
