#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "map/DistanceField.hpp"
#include "matching/PseudoMeasurement.hpp"
#include "options/FieldVisitor.hpp"

namespace unimap::pipeline {

// At most max_points of points, evenly strided (all when fewer): a cheap,
// deterministic subset for the search and the inlier shares.
std::vector<Eigen::Vector3f> StridedSubset(const std::vector<Eigen::Vector3f>& points, int max_points);

// Settings of the wide search (Reacquirer).
struct ReacquireOptions {
  int coarse_factor = 4;                // coarse cell edge, in map voxels
  double coarse_clamp_m = 3.0;          // the coarse field's reach: how far off a prediction may be (m)
  int coarse_iterations = 20;           // Gauss-Newton steps on the coarse field
  int fine_iterations = 10;             // then on the map's own field
  double inlier_distance_voxels = 1.5;  // a point within this of the map (at a pose) is an inlier
  double min_inlier_gain = 0.15;        // the searched pose must hold this many more of the points
                                        // (a share) than the matched one to replace it
  int max_points = 300;                 // points used (StridedSubset of the scan)
  double wide_sigma_voxels = 2.0;       // a prediction whose position sigma exceeds this many voxels
                                        // (or rotation sigma wide_sigma_rad) is searched from before matching
  double wide_sigma_rad = 0.05;         // (about 3 deg)
  double max_yaw_rad = 0.2;             // the grid search's heading reach, each side (rad)

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
};

// What a search found.
struct ReacquireResult {
  bool ok = false;  // a pose was found (see reason otherwise)
  std::string reason;
  matching::Vector6d error = matching::Vector6d::Zero();  // its error from the prediction [dp, dtheta]
  double inliers_predicted = 0.0;                         // share of the points on the map at the prediction
  double inliers_found = 0.0;                             // ... at the pose found
};

// Finds where a scan lies on the map when the prediction may be far off
// (a constant-velocity start while already moving, a kidnapped sensor, a
// prediction the filter trusted too much), on the scan's likelihood alone
// (no prior): a grid over horizontal position and heading around the
// prediction (3 predicted sigmas, at most coarse_clamp_m and max_yaw_rad;
// steps of half a coarse cell and of the heading that moves the scan's
// farthest points by that much) scored on a coarse view of the map's
// distance field (map::CoarsenField, reach coarse_clamp_m), then
// Gauss-Newton in 6 DOF from the best cell on the coarse field and on the
// field itself. The coarse field of a snapshot is built once (by its
// sequence) and reused until the map publishes another.
class Reacquirer {
 public:
  // Throws ConfigError when the options are invalid.
  explicit Reacquirer(const ReacquireOptions& options);

  // points_body: the scan (body frame; a few hundred, e.g. StridedSubset);
  // point_sigma_m, fine_clamp_m: the matcher's likelihood (GpfOptions).
  // predicted_covariance: the prediction's [dp, dtheta] covariance (sets the grid's reach).
  ReacquireResult Search(const std::shared_ptr<const map::DistanceField>& field,
                         const Eigen::Isometry3d& T_map_body_predicted, const matching::Matrix6d& predicted_covariance,
                         const std::vector<Eigen::Vector3f>& points_body, double point_sigma_m, double fine_clamp_m);
  // Share of points (body frame) within inlier_distance_voxels of the map at T_map_body.
  double InlierShare(const map::DistanceField& field, const Eigen::Isometry3d& T_map_body,
                     const std::vector<Eigen::Vector3f>& points_body) const;

  const ReacquireOptions& options() const { return options_; }

 private:
  // The best pose error of the grid (see the class comment) on the coarse field.
  matching::Vector6d GridSearch(const Eigen::Isometry3d& T_map_body_predicted,
                                const matching::Matrix6d& predicted_covariance,
                                const std::vector<Eigen::Vector3f>& points_body) const;

  ReacquireOptions options_;
  std::uint64_t coarse_sequence_ = 0;  // the snapshot coarse_ was built from
  const map::DistanceField* coarse_source_ = nullptr;
  std::shared_ptr<const map::DistanceField> coarse_;
};

}  // namespace unimap::pipeline
