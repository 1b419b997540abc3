#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "estimation/Eskf.hpp"
#include "estimation/MotionPrior.hpp"
#include "estimation/StaticInitializer.hpp"
#include "io/ScanRecord.hpp"
#include "map/DistanceMap.hpp"
#include "map/LineGapFill.hpp"
#include "map/ScanMap.hpp"
#include "pipeline/EventSink.hpp"
#include "pipeline/LocalizerOptions.hpp"
#include "pipeline/PoseHistory.hpp"
#include "pipeline/ScanAccumulator.hpp"
#include "pipeline/ScanMatcher.hpp"
#include "pipeline/StageTimes.hpp"
#include "pipeline/TrackingMonitor.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::pipeline {

// One 3D scan (N scans accumulated) as inserted into the map.
struct KeyScan {
  double time_s = 0.0;                                             // end time of its last scan
  Eigen::Isometry3d T_local_body = Eigen::Isometry3d::Identity();  // body pose then (local frame)
  std::vector<Eigen::Vector3f> points_local;                       // one point per map voxel, local frame
  std::vector<float> intensities;                                  // one per point, or empty (none in the input)
  Eigen::Vector3f sensor_origin_local = Eigen::Vector3f::Zero();   // mean sensor position of its scans
};

// Receives each 3D scan right after its insertion into the map.
using KeyScanSink = std::function<void(KeyScan&&)>;

// Counts of what happened to the input (skips are counted, never fatal).
struct LocalizerStats {
  std::size_t imu_samples = 0;
  std::size_t imu_out_of_order = 0;    // not after the previous sample: skipped
  std::size_t imu_gaps = 0;            // gaps above max_imu_gap_s bridged by holding the last sample
  std::size_t encoder_rejected = 0;    // not after the previous sample or non-finite: skipped
  std::size_t scans = 0;               // scans received
  std::size_t scans_matched = 0;       // with a GPF update
  std::size_t scans_unmatched = 0;     // localised by the IMU only (no map yet, too few points, GPF failure)
  std::size_t scans_static = 0;        // placed at the start pose, not matched (MotionSource::kStatic)
  std::size_t scans_searched = 0;      // matched with a wide search (uncertain prediction or poor match)
  std::size_t scans_reacquired = 0;    // of those, placed where the search found them (prediction was off)
  std::size_t scans_bad_input = 0;     // rejected by the payload (NaN points, times, ...): skipped
  std::size_t scans_no_encoder = 0;    // never covered by encoder samples: skipped
  std::size_t scans_out_of_order = 0;  // ending before an already processed scan: skipped
  std::size_t scans_no_motion = 0;     // no motion prediction (wheel-odometry gap): pose held, wide prior
  std::size_t odometry_samples = 0;    // wheel-odometry readings received
  std::size_t beams_dropped = 0;       // 2D beams without a valid return
  std::size_t map_insertions = 0;      // 3D scans inserted into the map
  std::size_t map_errors = 0;          // map updates refused (pose outside the map's range): skipped
  std::optional<estimation::InitialAttitude> initial_attitude;  // used for a given initial pose
  std::vector<std::string> messages;                            // the first few skip reasons, for the log
  TrackingReport tracking;  // whether the scans stopped matching the map (TrackingMonitor)
  StageTimes times;         // the localiser's stages (map stages: the map's UpdateTimes)
};

// Odometry-mode localiser (docs/design.md 1.1-1.3): IMU -> ESKF prediction; each
// scan is deskewed by the payload plugin, matched by the GPF against the
// distance map, and its pseudo measurement updates the ESKF; every N scans
// form a 3D scan inserted into the map (unless localising in a prior map).
class Localizer : public EventSink {
 public:
  // prior_map: localise in a fixed map (options.localize_only) instead of
  // building one. initial_pose: T_map_body at the end of the static window
  // (default: origin, attitude from gravity, yaw 0).
  Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin,
            std::unique_ptr<map::DistanceMap> prior_map = nullptr,
            std::optional<Eigen::Isometry3d> initial_pose = std::nullopt);
  // Odometry into a caller's map (e.g. a SubmapManager): every 3D scan is
  // inserted into map and then handed to on_key_scan (if set).
  Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin, std::shared_ptr<map::ScanMap> map,
            KeyScanSink on_key_scan);
  ~Localizer() override;

  // Data in time order (as DatasetReader::NextEvent delivers it).
  void AddImu(const ImuSample& sample) override;
  void AddEncoder(const EncoderSample& sample) override;
  void AddScan(io::ScanRecord scan) override;
  void AddOdometry(const OdometrySample& sample) override;
  // Processes every scan still waiting (end of data).
  void Finish() override;

  // Poses produced since the last call, in time order.
  std::vector<ScanPose> TakePoses() override;
  std::size_t ScansReceived() const override { return stats_.scans; }
  const LocalizerStats& stats() const { return stats_; }
  // The localiser's stage times with its map's update times.
  StageTimes Times() const;
  bool initialized() const { return eskf_.initialized(); }

 private:
  // The constructors above delegate here.
  Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin, std::shared_ptr<map::ScanMap> map,
            std::optional<Eigen::Isometry3d> initial_pose, KeyScanSink on_key_scan);
  void TryInitialize();
  // Without an IMU: starts the filter at the first scan (given pose or level origin).
  void InitializeWithoutImu(double time_s);
  // Predicts the state to t_end (IMU or motion prior; without an increment
  // the pose is held with a wide prior and the scan counted in scans_no_motion).
  void PredictTo(double t_end);
  // The body pose at time_s for deskewing: the history, and past the state's
  // time the motion prior's extrapolation (the IMU state is never behind).
  Eigen::Isometry3d MotionAt(double time_s) const;
  void ProcessReadyScans(bool finishing);
  void ProcessScan(const io::ScanRecord& scan);
  void Skip(std::size_t* counter, const std::string& message);

  LocalizerOptions options_;
  std::shared_ptr<PayloadPlugin> plugin_;
  std::shared_ptr<map::ScanMap> map_;
  KeyScanSink on_key_scan_;
  std::optional<Eigen::Isometry3d> initial_pose_;
  estimation::Eskf eskf_;
  std::unique_ptr<estimation::MotionPrior> prior_;  // set when options.motion.source is not kImu
  ScanMatcher matcher_;
  EncoderTrack encoder_;
  PoseHistory history_;
  ScanAccumulator accumulator_;
  std::optional<map::LineGapFill> line_fill_;  // set when options.line_gap_fill is
  std::vector<ImuSample> init_imu_;
  std::deque<io::ScanRecord> pending_;
  double last_imu_time_s_ = -1e300;
  double last_odometry_time_s_ = -1e300;
  double last_scan_end_s_ = -1e300;
  std::vector<ScanPose> poses_;
  LocalizerStats stats_;
  TrackingMonitor tracking_;  // fed every scan tried against a map
};

}  // namespace unimap::pipeline
