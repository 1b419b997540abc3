#pragma once
#include <cstdint>
#include <string>

#include "options/FieldVisitor.hpp"

namespace unimap::matching {

// Gaussian particle filter (Bry et al. 2012) settings.
struct GpfOptions {
  int num_particles = 500;                // pose hypotheses per scan
  double point_sigma_m = 0.1;             // per-point likelihood exp(-d^2 / 2 sigma^2)
  double clamp_distance_m = 0.5;          // distances above this count as this (outliers)
  double voxel_size_m = 0.1;              // scan downsampling voxel edge before weighting
  int max_points = 300;                   // random subset of the downsampled scan (0: all)
  double effective_points = 20.0;         // log-likelihood scaled to this many independent points
  bool planar = false;                    // sample x, y, yaw only (3-DOF)
  double min_sigma_position_m = 0.005;    // sampling covariance floor, position
  double min_sigma_rotation_rad = 0.001;  // sampling covariance floor, rotation
  double min_information_ratio = 1e-6;    // pseudo-measurement repair: information eigenvalue floor
  int refine_iterations = 0;              // Gauss-Newton steps from the GPF mean on the same posterior
                                          // (PoseRefiner; 0: plain GPF); the refined Laplace posterior
                                          // then replaces the particles' weighted mean and covariance
  bool point_to_plane = false;            // points whose cell at the predicted pose has a surface plane
                                          // (DistanceQuery::Planes) are measured against that plane by
                                          // every particle and the refinement (PlanePoint), the others
                                          // against the field
  bool planes_only = false;               // with point_to_plane: points without a plane are not measured
                                          // at all (they still count in the scan's n: ScanLikelihood)
  int threads = 1;                        // particles weighted in parallel (TBB)
  std::uint64_t seed = 1;                 // sampling seed (deterministic per scan sequence)

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::matching
