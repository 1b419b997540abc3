#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"

namespace unimap::pipeline {

// How the localiser got one scan's pose (`unimap run --trace`, trace.csv).
// Poses are [dp, dtheta] in the error coordinates of the ESKF (m, rad).
struct ScanDiagnostics {
  int points_used = 0;                 // after downsampling
  int points_unseen = 0;               // of those: not measured (far from the map)
  double effective_sample_size = 0.0;  // of the particle weights
  double mahalanobis_sq = 0.0;         // the update's innovation, squared
  double inflation = 1.0;              // the prediction's covariance was scaled by this
  double inlier_share = 0.0;           // scan points on the map at the matched pose
  Eigen::Matrix<double, 6, 1> correction = Eigen::Matrix<double, 6, 1>::Zero();    // applied to the prediction
  Eigen::Matrix<double, 6, 1> predicted_sd = Eigen::Matrix<double, 6, 1>::Zero();  // prior standard deviations
  Eigen::Matrix<double, 6, 1> measured_sd = Eigen::Matrix<double, 6, 1>::Zero();   // pseudo measurement's
  // The pseudo measurement itself: the pose error it measures against the
  // prediction (position m, rotation rad; the innovation of the update).
  Eigen::Matrix<double, 6, 1> innovation = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();     // after the update (map frame)
  Eigen::Vector3d accel_bias_m_s2 = Eigen::Vector3d::Zero();  // after the update
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // after the update
};

// The localised pose of one scan.
struct ScanPose {
  double time_s = 0.0;  // the scan's reference (end) time
  Eigen::Isometry3d T_map_body = Eigen::Isometry3d::Identity();
  bool matched = false;         // a GPF update was applied
  int points = 0;               // deskewed body points
  ScanDiagnostics diagnostics;  // how it was found
};

// What consumes a dataset's events in time order (as DatasetReader::NextEvent
// delivers them) and produces a pose per scan: the Localizer on its own, or
// the Mapper around it.
class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void AddImu(const ImuSample& sample) = 0;
  virtual void AddEncoder(const EncoderSample& sample) = 0;
  virtual void AddScan(io::ScanRecord scan) = 0;
  // A wheel-odometry reading (ignored unless a sink uses it).
  virtual void AddOdometry(const OdometrySample& /*sample*/) {}
  // Processes everything still waiting (end of data).
  virtual void Finish() = 0;
  // Poses produced since the last call, in time order.
  virtual std::vector<ScanPose> TakePoses() = 0;
  // Scans received so far (for progress reports).
  virtual std::size_t ScansReceived() const = 0;
};

}  // namespace unimap::pipeline
