#pragma once
// Map quality without ground truth (Razlaw et al. 2015, "Evaluation of
// registration methods for sparse 3D laser scans"): how crisp a map is,
// from its points alone.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace unimap::eval {

struct MapQualityOptions {
  double radius_m = 0.3;            // neighbourhood of a point: the map points within this distance (m)
  int min_neighbors = 10;           // points with fewer (themselves included) are not evaluated
  double planar_ratio = 0.1;        // planar: smallest covariance eigenvalue <= this times the middle one
  std::size_t max_points = 200000;  // evaluated points at most (an evenly strided subset; 0: all)
  double min_variance_m2 = 1e-8;    // eigenvalue floor (m^2) so that a noise-free plane has a finite entropy

  bool IsValid(std::string* why) const;
};

struct MapQuality {
  std::size_t points = 0;         // map points
  std::size_t evaluated = 0;      // of the evaluated subset, those with min_neighbors neighbours
  double mean_map_entropy = 0.0;  // mean of 0.5 ln det(2 pi e Sigma) over evaluated points (nats; lower is crisper)
  double mean_plane_variance_m2 = 0.0;  // mean smallest eigenvalue of Sigma: the variance across the local
                                        // surface (m^2; a wall of thickness noise sigma gives sigma^2)
  double planar_share = 0.0;            // share of evaluated points whose neighbourhood is planar
};

// Sigma is the covariance of the points within radius_m of each evaluated
// point. Deterministic for the same points in the same order. Throws
// std::invalid_argument when the options are invalid; no point evaluated
// leaves the means at 0 (evaluated = 0).
MapQuality ComputeMapQuality(const std::vector<Eigen::Vector3f>& points_map, const MapQualityOptions& options = {});

}  // namespace unimap::eval
