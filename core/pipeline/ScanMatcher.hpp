#pragma once
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "map/DistanceField.hpp"
#include "matching/GaussianParticleFilter.hpp"
#include "pipeline/LocalizerOptions.hpp"
#include "pipeline/Reacquirer.hpp"

namespace unimap::pipeline {

// One scan matched against the map.
struct ScanMatchResult {
  matching::GpfResult match;  // the measurement for the filter (match.ok)
  double inflation = 1.0;     // scale the filter's motion covariance by this before the update
                              // (Eskf::InflateMotionCovariance): the prediction was this far off
  bool searched = false;      // a wide search ran (Reacquirer)
  bool reacquired = false;    // and its pose replaced the prediction's
  double inliers = 0.0;       // share of the scan's points on the map at the matched pose
};

// The localiser's measurement of a scan (docs/design.md 1.3 with a safety net):
// the Gaussian particle filter and its refinement around the prediction,
// unless the prediction is too uncertain for the map's basin (a sensor
// whose velocity is not known yet) or the match leaves most of the scan off
// the map. Then a wide search (Reacquirer) looks for the pose from the
// prediction; its pose is taken when it holds at least as much of the scan
// (an uncertain prediction) or clearly more (a poor match: the prediction
// was wrong). The filter's uncertainty is then inflated until that pose is
// a plausible (2 sigma) correction, and the refinement starts from it.
class ScanMatcher {
 public:
  explicit ScanMatcher(const LocalizerOptions& options);

  // points_body: the deskewed scan; line: a 2D line scan.
  // predicted_covariance: the prediction's [dp, dtheta] covariance (the
  // particles' prior). map_relative_covariance: the part of it that moves a
  // point relative to the map (estimation::Eskf::
  // PoseCovarianceRelativeToStart). Points farther from the map at the
  // prediction than LocalizerOptions::max_predicted_distance_m are not
  // measured; that limit grows by sweep_gate_sigmas of the map-relative
  // uncertainty: the point's range times rotation, and for a sweep (line
  // false) also position.
  ScanMatchResult Match(const std::shared_ptr<const map::DistanceField>& field, const Eigen::Isometry3d& T_predicted,
                        const matching::Matrix6d& predicted_covariance,
                        const matching::Matrix6d& map_relative_covariance,
                        const std::vector<Eigen::Vector3f>& points_body, bool line);

 private:
  LocalizerOptions options_;
  matching::GaussianParticleFilter gpf_;
  Reacquirer reacquirer_;
};

}  // namespace unimap::pipeline
