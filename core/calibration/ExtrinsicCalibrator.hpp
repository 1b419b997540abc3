#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/CalibrationOptions.hpp"
#include "calibration/LidarCorrection.hpp"

namespace unimap::calibration {

// One return for calibration: what the LiDAR measured and where the LiDAR was
// when it did, by the platform's extrinsic (T_world_lidar at the firing time:
// the body's pose, times T_body_lidar of the payload's model).
struct CalibrationReturn {
  Eigen::Vector3f p_lidar = Eigen::Vector3f::Zero();                  // LiDAR frame (m)
  Eigen::Quaternionf q_world_lidar = Eigen::Quaternionf::Identity();  // T_world_lidar's rotation
  Eigen::Vector3f t_world_lidar = Eigen::Vector3f::Zero();            // ... and translation (m)
  std::uint32_t scan = 0;                                             // the scan it belongs to (ordered by time)
};

// What ExtrinsicCalibrator found. Six-vectors are [translation x y z (m),
// rotation x y z (rad)] of the correction, in the LiDAR frame.
struct CalibrationResult {
  bool ok = false;      // false: no planar neighbourhood was seen from two views (failure says why)
  std::string failure;  // empty when ok
  // The correction X: the LiDAR's pose in the body is T_body_lidar X, so a
  // payload whose extrinsic ends with T_*_lidar (T_motor_lidar, T_body_lidar)
  // replaces it by T_*_lidar X.
  Eigen::Isometry3d T_lidar_corrected = Eigen::Isometry3d::Identity();
  Matrix6d covariance = Matrix6d::Zero();         // of the correction (data and the weak prior)
  Vector6d information_ratio = Vector6d::Zero();  // data / prior information per direction below, ascending
  Matrix6d directions = Matrix6d::Identity();     // columns: those directions (unit, in prior-sigma units)
  int observable = 0;                             // directions with information_ratio >= min_information_ratio
  std::size_t neighbourhoods = 0;                 // planes seen from another view, in the last round
  std::size_t residuals = 0;                      // ... and the returns measured against them
  double rms_start_m = 0.0;                       // their RMS distance from those planes before the first step (m)
  double rms_end_m = 0.0;                         // ... and at the correction (m)
  int rounds = 0;                                 // neighbourhoods chosen
  int iterations = 0;                             // Newton steps in all
  bool converged = false;                         // the last round's steps ended within the tolerances
};

// Finds the LiDAR extrinsic with which the views of a rig's map agree: each
// surface seen from several views (the LiDAR turned or moved between them)
// should be one surface. Around an even subset of the returns, the returns
// of the centre's view are measured against the plane of those of other views
// (CrossViewPlane; a round chooses them), and Gauss-Newton steps of the
// correction minimise those distances (Huber loss) plus a weak prior towards
// the platform's extrinsic; rounds choose the neighbourhoods anew with the
// corrected map until one no longer moves it. (Measuring how flat the
// union of all views is, the plane variance of Razlaw et al., is not used:
// deforming the whole map can flatten it, so its minimum need not be the
// truth; measured in docs/calibration.md.) Steps
// are taken only along the directions the data observe (Zhang, Kaess & Singh
// 2016, "On degeneracy of optimization-based state estimation problems"):
// the others (e.g. a standing rotating rig's offset along its motor axis,
// which moves the whole map) keep the platform's values and are reported.
class ExtrinsicCalibrator {
 public:
  // Throws std::invalid_argument when the options are invalid.
  explicit ExtrinsicCalibrator(const CalibrationOptions& options = {});

  // Deterministic for the same returns in the same order.
  CalibrationResult Calibrate(const std::vector<CalibrationReturn>& returns) const;

  // The returns in the world frame with the correction applied.
  static std::vector<Eigen::Vector3f> Assemble(const std::vector<CalibrationReturn>& returns,
                                               const Eigen::Isometry3d& T_lidar_corrected);

 private:
  CalibrationOptions options_;
};

}  // namespace unimap::calibration
