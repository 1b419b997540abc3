#include "pipeline/Localizer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "estimation/MakeMotionPrior.hpp"
#include "estimation/So3.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "pipeline/FieldDistanceQuery.hpp"
#include "pipeline/InitialState.hpp"
#include "unimap/Errors.hpp"
#include "unimap/LineScan.hpp"

namespace unimap::pipeline {
namespace {

constexpr std::size_t kMaxMessages = 20;

LocalizerOptions Checked(LocalizerOptions options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "", "localizer options: " + why);
  return options;
}

// The map of a Localizer that owns it: the prior, or a new one from the
// (checked) options.
std::shared_ptr<map::ScanMap> OwnMap(const LocalizerOptions& options, std::unique_ptr<map::DistanceMap> prior_map) {
  if (prior_map) return prior_map;
  return std::make_shared<map::DistanceMap>(Checked(options).map);
}

}  // namespace

Localizer::Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin,
                     std::unique_ptr<map::DistanceMap> prior_map, std::optional<Eigen::Isometry3d> initial_pose)
    : Localizer(options, std::move(plugin), OwnMap(options, std::move(prior_map)), initial_pose, nullptr) {}

Localizer::Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin, std::shared_ptr<map::ScanMap> map,
                     KeyScanSink on_key_scan)
    : Localizer(options, std::move(plugin), std::move(map), std::nullopt, std::move(on_key_scan)) {}

Localizer::Localizer(LocalizerOptions options, std::shared_ptr<PayloadPlugin> plugin, std::shared_ptr<map::ScanMap> map,
                     std::optional<Eigen::Isometry3d> initial_pose, KeyScanSink on_key_scan)
    : options_(Checked(options)),
      plugin_(std::move(plugin)),
      map_(std::move(map)),
      on_key_scan_(std::move(on_key_scan)),
      initial_pose_(initial_pose),
      eskf_(options_.eskf),
      prior_(estimation::MakeMotionPrior(options_.motion)),
      matcher_(options_),
      encoder_(std::vector<EncoderSample>{}, 0.5),
      history_(2.0),
      accumulator_(options_.scans_per_3d_scan) {
  if (!plugin_) throw std::invalid_argument("Localizer: no payload plugin");
  if (!map_) throw std::invalid_argument("Localizer: no map");
  if (options_.line_gap_fill) line_fill_.emplace(*options_.line_gap_fill);
}

Localizer::~Localizer() = default;

void Localizer::Skip(std::size_t* counter, const std::string& message) {
  ++*counter;
  if (stats_.messages.size() < kMaxMessages) stats_.messages.push_back(message);
}

void Localizer::AddImu(const ImuSample& sample) {
  ++stats_.imu_samples;
  if (prior_) return;  // predictions come from the motion prior
  if (!(sample.time_s > last_imu_time_s_) || !sample.accel_m_s2.allFinite() || !sample.gyro_rad_s.allFinite()) {
    Skip(&stats_.imu_out_of_order,
         "IMU sample at " + std::to_string(sample.time_s) + " s is not after the previous one or not finite: skipped");
    return;
  }
  last_imu_time_s_ = sample.time_s;
  {
    StageTimer timer(&stats_.times.eskf_s);
    if (!eskf_.initialized()) {
      init_imu_.push_back(sample);
      TryInitialize();
    } else if (!eskf_.Propagate(sample)) {
      ++stats_.imu_gaps;
      eskf_.RestartImu(sample);
    }
    if (eskf_.initialized()) history_.Add(eskf_.state().time_s, eskf_.state().T_world_body());
  }
  ProcessReadyScans(false);
}

void Localizer::AddEncoder(const EncoderSample& sample) {
  if (!encoder_.empty() && !(sample.time_s > encoder_.end_time_s())) {
    Skip(&stats_.encoder_rejected,
         "encoder sample at " + std::to_string(sample.time_s) + " s is not after the previous one: skipped");
    return;
  }
  try {
    encoder_.Append(sample);
  } catch (const InputError& e) {
    Skip(&stats_.encoder_rejected, std::string("encoder sample: ") + e.what());
    return;
  }
  // Keep a couple of seconds: enough for any scan still waiting.
  encoder_.DropBefore(sample.time_s - 2.0);
  ProcessReadyScans(false);
}

void Localizer::AddScan(io::ScanRecord scan) {
  ++stats_.scans;
  pending_.push_back(std::move(scan));
  ProcessReadyScans(false);
}

void Localizer::AddOdometry(const OdometrySample& sample) {
  ++stats_.odometry_samples;
  if (!prior_) return;
  prior_->AddOdometry(sample);
  last_odometry_time_s_ = std::max(last_odometry_time_s_, sample.time_s);
  ProcessReadyScans(false);
}

void Localizer::Finish() { ProcessReadyScans(true); }

void Localizer::InitializeWithoutImu(double time_s) {
  estimation::NavState state;
  state.time_s = time_s;
  if (initial_pose_) {
    state.p_world_body_m = initial_pose_->translation();
    state.q_world_body = Eigen::Quaterniond(initial_pose_->linear());
  }
  eskf_.Initialize(state);
  history_.Add(time_s, state.T_world_body());
}

void Localizer::PredictTo(double t_end) {
  StageTimer timer(&stats_.times.eskf_s);
  if (!prior_) {
    eskf_.PropagateTo(t_end);
    return;
  }
  estimation::MotionPrediction prediction = prior_->Predict(eskf_.state().time_s, t_end);
  if (!prediction.ok) {
    // No increment (e.g. an odometry gap): hold the pose with the
    // uncertainty of an unknown motion at the constant-velocity sigmas, so
    // the match can still find it; counted, not skipped.
    Skip(&stats_.scans_no_motion,
         "scan ending at " + std::to_string(t_end) + " s: " + prediction.reason + "; pose held with a wide prior");
    prediction.T_prev_next.setIdentity();
    prediction.covariance = estimation::UnmodeledMotionCovariance(options_.motion, t_end - eskf_.state().time_s);
  }
  eskf_.PredictPose(t_end, prediction.T_prev_next, prediction.covariance);
}

Eigen::Isometry3d Localizer::MotionAt(double time_s) const {
  const double state_time_s = eskf_.state().time_s;
  if (!prior_ || time_s <= state_time_s) return history_.At(time_s);
  const estimation::MotionPrediction ahead = prior_->Predict(state_time_s, time_s);
  return ahead.ok ? eskf_.state().T_world_body() * ahead.T_prev_next : history_.At(time_s);
}

StageTimes Localizer::Times() const {
  StageTimes times = stats_.times;
  const map::MapUpdateTimes map = map_->UpdateTimes();
  times.map_surface_s = map.surface_s;
  times.map_distance_s = map.distance_s;
  times.map_export_s = map.export_s;
  return times;
}

std::vector<ScanPose> Localizer::TakePoses() {
  std::vector<ScanPose> out;
  out.swap(poses_);
  return out;
}

void Localizer::TryInitialize() {
  if (init_imu_.back().time_s - init_imu_.front().time_s < options_.static_init_s) return;
  InitialState start = InitialStateFromWindow(init_imu_, initial_pose_, options_);
  stats_.initial_attitude = start.attitude;
  for (std::string& note : start.notes) {
    if (stats_.messages.size() < kMaxMessages) stats_.messages.push_back(std::move(note));
  }
  estimation::ErrorCovariance covariance = estimation::InitialCovariance(options_.eskf);
  if (start.sigma_gyro_bias_rad_s) {
    covariance.block<3, 3>(estimation::error_index::kBg, estimation::error_index::kBg) =
        start.sigma_gyro_bias_rad_s->cwiseAbs2().asDiagonal();
  }
  eskf_.Initialize(start.state, covariance);
  if (start.sigma_accel_m_s2 || start.sigma_gyro_rad_s) {
    eskf_.SetImuNoise(start.sigma_accel_m_s2.value_or(options_.eskf.sigma_accel_m_s2),
                      start.sigma_gyro_rad_s.value_or(options_.eskf.sigma_gyro_rad_s));
  }
  eskf_.Propagate(init_imu_.back());
  init_imu_.clear();
  init_imu_.shrink_to_fit();
}

void Localizer::ProcessReadyScans(bool finishing) {
  while (!pending_.empty()) {
    const io::ScanRecord& scan = pending_.front();
    const double t_end = io::ScanEndTime(scan);
    const double newest =
        std::max({last_imu_time_s_, last_odometry_time_s_, encoder_.empty() ? -1e300 : encoder_.end_time_s()});
    const bool stale = newest - t_end >= options_.max_scan_latency_s;
    // Without an IMU the filter starts at the first scan its prior covers
    // (or, with no prior data at all, once the scan is stale).
    if (!eskf_.initialized() && prior_ && (prior_->ReadyFor(t_end) || finishing || stale))
      InitializeWithoutImu(io::ScanStartTime(scan));
    if (!eskf_.initialized()) {
      if (!finishing) return;
      Skip(&stats_.scans_unmatched, "scan at " + std::to_string(t_end) + " s: no IMU to initialise: skipped");
      pending_.pop_front();
      continue;
    }
    const bool motion_ready = prior_ ? prior_->ReadyFor(t_end) : last_imu_time_s_ >= t_end;
    const bool encoder_ready = !plugin_->UsesEncoder() || (!encoder_.empty() && encoder_.end_time_s() >= t_end);
    if (!finishing && !(motion_ready && encoder_ready) && !stale) return;
    if (plugin_->UsesEncoder() && !encoder_ready && !finishing) {
      Skip(&stats_.scans_no_encoder, "scan ending at " + std::to_string(t_end) + " s has no encoder coverage: skipped");
    } else if (t_end < last_scan_end_s_) {
      Skip(&stats_.scans_out_of_order,
           "scan ending at " + std::to_string(t_end) + " s ends before the previous scan: skipped");
    } else {
      ProcessScan(scan);
    }
    pending_.pop_front();
  }
}

void Localizer::ProcessScan(const io::ScanRecord& scan) {
  const double t_end = io::ScanEndTime(scan);
  RawScan converted_line;
  const RawScan* raw = std::get_if<RawScan>(&scan);  // a 3D scan is deskewed where it lies
  if (const auto* line = std::get_if<LineScan>(&scan)) {
    try {
      StageTimer timer(&stats_.times.deskew_s);
      LineScanConversion converted = LineScanToRawScan(*line);
      stats_.beams_dropped += converted.dropped;
      converted_line = std::move(converted.scan);
      raw = &converted_line;
    } catch (const InputError& e) {
      Skip(&stats_.scans_bad_input, "line scan at " + std::to_string(t_end) + " s: " + e.what());
      return;
    }
    if (raw->points.empty()) {
      Skip(&stats_.scans_bad_input, "line scan at " + std::to_string(t_end) + " s has no valid return");
      return;
    }
  }
  // With the IMU the state runs with its samples: predict to the scan's end
  // (holding the last sample if it lags) for the deskew. With a motion prior
  // the state is predicted to the scan's reference time once the deskew has
  // told it (a snapshot is taken at its start), and the deskew extrapolates
  // with the prior meanwhile: the state and the pose it is matched as must
  // share one time.
  if (!prior_ && eskf_.state().time_s < t_end) {
    PredictTo(t_end);
    history_.Add(eskf_.state().time_s, eskf_.state().T_world_body());
  }
  BodyScan body;
  try {
    StageTimer timer(&stats_.times.deskew_s);
    body = plugin_->Deskew(*raw, encoder_, [this](double t) { return MotionAt(t); });
  } catch (const InputError& e) {
    Skip(&stats_.scans_bad_input, "scan at " + std::to_string(t_end) + " s: " + e.what());
    return;
  }
  last_scan_end_s_ = t_end;
  // The pose is the body's at the deskewed scan's reference time: the end of
  // the sweep, or the time a snapshot (already deskewed) cloud was taken.
  const double t_ref = std::min(body.reference_time_s, t_end);
  if (prior_ && eskf_.state().time_s < t_ref) {
    PredictTo(t_ref);
    history_.Add(eskf_.state().time_s, eskf_.state().T_world_body());
  }
  std::vector<Eigen::Vector3f> points_body;
  points_body.reserve(body.points.size());
  for (const Point& p : body.points) points_body.push_back(p.position_m.cast<float>());

  // GPF -> pseudo measurement -> ESKF update (docs/design.md 1.3). The state may
  // be a few ms past t_end (waiting for the encoder): the pose error is
  // applied to the current state.
  const Eigen::Isometry3d T_predicted = history_.At(t_ref);
  matching::Vector6d correction = matching::Vector6d::Zero();
  bool matched = false;
  ScanDiagnostics diagnostics;
  diagnostics.predicted_sd = eskf_.PoseCovariance().diagonal().cwiseSqrt();
  std::shared_ptr<const map::DistanceField> field = map_->Snapshot();
  // A static body has nothing to estimate: its scans are placed, not matched.
  const bool static_body = options_.motion.source == estimation::MotionSource::kStatic;
  if (!static_body && field->CellCount() > 0 && static_cast<int>(points_body.size()) >= options_.min_points_to_match) {
    const bool is_line = std::holds_alternative<LineScan>(scan);
    double match_s = 0.0;
    ScanMatchResult matched_scan;
    {
      StageTimer timer(&match_s);
      matched_scan = matcher_.Match(field, T_predicted, eskf_.PoseCovariance(), eskf_.PoseCovarianceRelativeToStart(),
                                    points_body, is_line);
    }
    const matching::GpfResult& match = matched_scan.match;
    stats_.scans_searched += matched_scan.searched ? 1 : 0;
    stats_.scans_reacquired += matched_scan.reacquired ? 1 : 0;
    diagnostics.inflation = matched_scan.inflation;
    diagnostics.inlier_share = matched_scan.inliers;
    stats_.times.match_s += match_s - match.downsample_s;
    stats_.times.downsample_s += match.downsample_s;
    diagnostics.points_used = match.points_used;
    diagnostics.points_unseen = match.points_unseen;
    diagnostics.effective_sample_size = match.effective_sample_size;
    if (match.ok) {
      StageTimer timer(&stats_.times.eskf_s);
      eskf_.InflateMotionCovariance(matched_scan.inflation);
      const estimation::PoseUpdateResult update = eskf_.UpdatePoseError(match.measurement.z, match.measurement.R);
      diagnostics.measured_sd = match.measurement.R.diagonal().cwiseSqrt();
      diagnostics.innovation = match.measurement.z;
      diagnostics.mahalanobis_sq = update.mahalanobis_sq;
      if (update.applied) {
        correction = update.error_correction;
        matched = true;
      }
    }
    tracking_.Add(t_ref, matched ? matched_scan.inliers : 0.0);
    stats_.tracking = tracking_.report();
  }
  ++(static_body ? stats_.scans_static : matched ? stats_.scans_matched : stats_.scans_unmatched);
  const Eigen::Isometry3d T_map_body = estimation::ApplyPoseError(T_predicted, correction);
  if (matched) {
    history_.Clear();
    if (t_ref < eskf_.state().time_s) history_.Add(t_ref, T_map_body);
    history_.Add(eskf_.state().time_s, eskf_.state().T_world_body());
  }
  diagnostics.correction = correction;
  diagnostics.velocity_m_s = eskf_.state().v_world_m_s;
  diagnostics.accel_bias_m_s2 = eskf_.state().accel_bias_m_s2;
  diagnostics.gyro_bias_rad_s = eskf_.state().gyro_bias_rad_s;
  poses_.push_back({t_ref, T_map_body, matched, static_cast<int>(points_body.size()), diagnostics});
  if (prior_) prior_->Observe(t_ref, T_map_body);

  const Eigen::Vector3f sensor_map =
      (T_map_body * plugin_->BodyFromLidarAt(encoder_, t_ref).translation()).cast<float>();
  if (options_.localize_only) {
    try {
      map_->UpdateSensorPosition(sensor_map);
      if (options_.wait_for_map) map_->WaitForUpdates();
    } catch (const InputError& e) {
      Skip(&stats_.map_errors, "map at " + std::to_string(t_end) + " s: " + e.what());
    }
    return;
  }
  std::vector<Eigen::Vector3f> points_map;
  points_map.reserve(points_body.size());
  const Eigen::Isometry3f T = T_map_body.cast<float>();
  for (const auto& p : points_body) points_map.push_back(T * p);
  std::vector<Eigen::Vector3f> filled;  // the distance map only: key scans keep the measured points
  if (const auto* line = std::get_if<LineScan>(&scan); line && line_fill_) {
    filled = line_fill_->Add(t_end, sensor_map, map::LineReturns(*line, body, points_map));
  }
  // Intensities go with the points into the key scans (and the final map)
  // when the input has any: a scan of zeros has none to keep.
  std::vector<float> intensities;
  if (std::any_of(body.points.begin(), body.points.end(), [](const Point& p) { return p.intensity != 0.0f; })) {
    intensities.reserve(body.points.size());
    for (const Point& p : body.points) intensities.push_back(p.intensity);
  }
  if (accumulator_.Add(points_map, intensities, sensor_map, filled)) {
    Eigen::Vector3f origin;
    // One point per map voxel: the octree update costs per point, occupancy
    // barely changes.
    std::vector<Eigen::Vector3f> scan3d;
    std::vector<float> scan3d_intensities;
    {
      StageTimer timer(&stats_.times.downsample_s);
      std::vector<float> all_intensities;
      const std::vector<Eigen::Vector3f> all = accumulator_.Take(&origin, &all_intensities, &filled);
      const std::vector<std::size_t> kept = matching::VoxelFirstIndices(all, options_.map.resolution_m);
      scan3d.reserve(kept.size());
      for (const std::size_t i : kept) scan3d.push_back(all[i]);
      if (!all_intensities.empty()) {
        scan3d_intensities.reserve(kept.size());
        for (const std::size_t i : kept) scan3d_intensities.push_back(all_intensities[i]);
      }
    }
    try {
      KeyScan key;
      if (on_key_scan_) key = {t_ref, T_map_body, scan3d, std::move(scan3d_intensities), origin};
      if (!filled.empty()) {
        StageTimer timer(&stats_.times.downsample_s);
        scan3d.insert(scan3d.end(), filled.begin(), filled.end());
        scan3d = matching::VoxelDownsample(scan3d, options_.map.resolution_m, 0, 0);
      }
      map_->InsertScan(std::move(scan3d), origin);
      ++stats_.map_insertions;
      if (options_.wait_for_map) map_->WaitForUpdates();
      if (on_key_scan_) on_key_scan_(std::move(key));
    } catch (const InputError& e) {  // e.g. a diverged pose outside the octree's key range
      Skip(&stats_.map_errors, "map insertion at " + std::to_string(t_end) + " s: " + e.what());
    }
  }
}

}  // namespace unimap::pipeline
