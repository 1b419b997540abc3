#include "RunOutputs.hpp"

#include <optional>

#include "CommandLine.hpp"
#include "FolderReport.hpp"
#include "MapEvaluation.hpp"
#include "OutputFrames.hpp"
#include "PlatformJson.hpp"
#include "SignalGuard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "estimation/So3.hpp"
#include "eval/AtomicFile.hpp"
#include "eval/EvaluationReport.hpp"
#include "eval/MetricRows.hpp"
#include "eval/TrajectoryAssociation.hpp"
#include "eval/TrajectoryErrors.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/PartialFile.hpp"
#include "io/TumTrajectory.hpp"

namespace unimap::cli {
namespace {

// What to do when no scan was matched, from the localiser's counts.
std::string NoMatchAdvice(const RunOutputsInput& in) {
  const pipeline::LocalizerStats& s = in.stats;
  if (s.scans_no_encoder == s.scans) {
    return "Every scan lacked encoder coverage: the payload needs a motor encoder stream (encoder.csv) "
           "covering the scans.";
  }
  if (s.scans_bad_input == s.scans) {
    return "The payload rejected every scan (see the skip messages): check that the platform's plugin "
           "matches the data.";
  }
  if (s.imu_samples == 0 && in.motion == "imu") {
    return "The dataset has no IMU data: run with --motion odometry or --motion constant-velocity.";
  }
  return "Check that the platform file matches the sensor (payload, range limits, extrinsics) and see the "
         "skip messages above.";
}

constexpr double kRadToDeg = 180.0 / M_PI;

// A number for run.json: null when undefined (no pose associated).
double OrNull(double value, bool defined) { return defined ? value : std::numeric_limits<double>::quiet_NaN(); }

}  // namespace

WorldFrameErrors ComputeWorldFrameErrors(const std::vector<StampedPose>& estimate,
                                         const std::vector<StampedPose>& truth) {
  const eval::TrajectoryAssociation association = eval::AssociateTrajectories(estimate, truth);
  WorldFrameErrors e;
  double sum_p2 = 0.0, sum_r2 = 0.0;
  for (const eval::AssociatedPose& pair : association.pairs) {
    const double dp = (pair.T_est_body.translation() - pair.T_true_body.translation()).norm();
    // Rotation error log(q_est^-1 q_true) (docs/design.md 1), its angle.
    const Eigen::Quaterniond q_est(pair.T_est_body.linear());
    const Eigen::Quaterniond q_true(pair.T_true_body.linear());
    const double theta_deg = estimation::LogQ(q_est.conjugate() * q_true).norm() * kRadToDeg;
    sum_p2 += dp * dp;
    sum_r2 += theta_deg * theta_deg;
    e.position_max_error_m = std::max(e.position_max_error_m, dp);
    e.rotation_max_error_deg = std::max(e.rotation_max_error_deg, theta_deg);
  }
  e.poses = association.pairs.size();
  if (e.poses > 0) {
    e.position_rmse_m = std::sqrt(sum_p2 / static_cast<double>(e.poses));
    e.rotation_rmse_deg = std::sqrt(sum_r2 / static_cast<double>(e.poses));
  }
  return e;
}

// The warning of a run whose scans stopped matching the map (empty when they did not).
std::string TrackingWarning(const pipeline::TrackingReport& t) {
  if (!t.lost()) return "";
  std::ostringstream text;
  text << std::fixed << std::setprecision(3) << "the scans stopped matching the map at " << t.first_poor_time_s
       << " s (" << std::setprecision(1) << t.first_poor_time_s - t.first_time_s << " s after matching began): over "
       << pipeline::TrackingMonitor::kWindowS << " s less than " << std::setprecision(0)
       << 100.0 * pipeline::TrackingMonitor::kMinInlierShare << " % of their points lay near it ("
       << std::setprecision(1) << t.poor_s << " s in all, worst " << std::setprecision(2) << t.worst_window_share
       << "). The odometry was probably lost there; the trajectory and the map after it are unreliable"
          " (run.json: localizer.tracking).";
  return text.str();
}

Json LocalizerStatsJson(const pipeline::LocalizerStats& s) {
  Json o = Json::object();
  o["imu_samples"] = s.imu_samples;
  o["imu_out_of_order"] = s.imu_out_of_order;
  o["imu_gaps"] = s.imu_gaps;
  o["encoder_rejected"] = s.encoder_rejected;
  o["scans_matched"] = s.scans_matched;
  o["scans_unmatched"] = s.scans_unmatched;
  o["scans_static"] = s.scans_static;
  o["scans_searched"] = s.scans_searched;
  o["scans_reacquired"] = s.scans_reacquired;
  o["scans_bad_input"] = s.scans_bad_input;
  o["scans_no_encoder"] = s.scans_no_encoder;
  o["scans_out_of_order"] = s.scans_out_of_order;
  o["scans_no_motion"] = s.scans_no_motion;
  o["odometry_samples"] = s.odometry_samples;
  o["beams_dropped"] = s.beams_dropped;
  o["map_insertions"] = s.map_insertions;
  o["map_errors"] = s.map_errors;
  o["messages"] = s.messages;
  const pipeline::TrackingReport& t = s.tracking;
  Json tracking = Json::object();
  tracking["window_s"] = pipeline::TrackingMonitor::kWindowS;
  tracking["min_inlier_share"] = pipeline::TrackingMonitor::kMinInlierShare;
  tracking["scans"] = t.scans;
  const bool judged = t.worst_window_time_s >= 0.0;
  tracking["first_time_s"] = OrNull(t.first_time_s, t.scans > 0);
  tracking["lost"] = t.lost();
  tracking["first_poor_time_s"] = OrNull(t.first_poor_time_s, t.lost());
  tracking["poor_s"] = t.poor_s;
  tracking["worst_window_inlier_share"] = OrNull(t.worst_window_share, judged);
  tracking["worst_window_time_s"] = OrNull(t.worst_window_time_s, judged);
  tracking["messages"] = t.lost() ? std::vector<std::string>{TrackingWarning(t)} : std::vector<std::string>{};
  o["tracking"] = tracking;
  return o;
}

Json StageTimesJson(const pipeline::StageTimes& t, double processing_s, bool print) {
  const std::pair<const char*, double> stages[] = {{"deskew_s", t.deskew_s},
                                                   {"downsample_s", t.downsample_s},
                                                   {"match_s", t.match_s},
                                                   {"eskf_s", t.eskf_s},
                                                   {"map_surface_s", t.map_surface_s},
                                                   {"map_distance_s", t.map_distance_s},
                                                   {"map_export_s", t.map_export_s},
                                                   {"loop_search_s", t.loop_search_s},
                                                   {"optimisation_s", t.optimization_s},
                                                   {"outputs_s", t.outputs_s}};
  Json o = Json::object();
  std::string line = "stages (s):";
  for (const auto& [key, seconds] : stages) {
    o[key] = seconds;
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), " %.*s %.2f", static_cast<int>(std::strlen(key) - 2), key, seconds);
    line += buffer;
  }
  o["processing_s"] = processing_s;
  if (print) std::cout << line << '\n';
  return o;
}

void PrintRunProgress(const pipeline::RunProgress& p) {
  const double rtf = p.wall_s > 0.0 ? p.data_time_s / p.wall_s : 0.0;
  std::fprintf(stderr, "\r%zu scans | %.0f scans/s | %.1fx real time", p.scans,
               p.wall_s > 0.0 ? static_cast<double>(p.scans) / p.wall_s : 0.0, rtf);
  if (p.data_duration_s > 0.0 && rtf > 0.0) {
    std::fprintf(stderr, " | %.0f%% | ETA %.0f s   ", 100.0 * p.data_time_s / p.data_duration_s,
                 std::max(0.0, (p.data_duration_s - p.data_time_s) / rtf));
  }
  std::fflush(stderr);
}

int WriteRunOutputs(const RunOutputsInput& in) {
  const pipeline::RunSummary& summary = in.summary;
  const std::filesystem::path out = in.out_dir;
  const std::filesystem::path truth_file = in.TruthFile();
  const bool evaluate = in.has_groundtruth && summary.poses_written >= 2;
  const std::filesystem::path trajectory = out / in.trajectory_file;

  Json run = Json::object();
  run["realtime_factor"] = summary.realtime_factor;
  run["processing_s"] = summary.processing_s;
  run["data_duration_s"] = summary.data_duration_s;
  run["scans"] = in.stats.scans;
  run["poses"] = summary.poses_written;
  run["peak_rss_mb"] = summary.peak_rss_mb;
  run["interrupted"] = summary.interrupted || SignalGuard::Received() != 0;
  run["error"] = summary.error;
  run["platform"] = in.platform_file;
  run["payload"] = in.payload;
  run["dataset"] = in.data_dir;
  run["gpf_threads"] = in.gpf_threads;
  run["gpf_seed"] = static_cast<std::size_t>(in.gpf_seed);
  if (!in.motion.empty()) {
    run["motion"] = in.motion;
    run["motion_reason"] = in.motion_reason;
  }
  run["localizer"] = LocalizerStatsJson(in.stats);
  run["command"] = CommandLine();                                // the report's source of options
  run["parameters"] = PlatformParametersJson(in.platform_file);  // effective values and their sources
  for (const auto& [key, object] : in.extras) run[key] = object;
  run["frames"] = OutputFramesJson(out, in.world_frame_errors);
  // The truth and the estimate, read once for every evaluation below.
  std::vector<StampedPose> truth;
  std::vector<StampedPose> estimate;
  if (evaluate) {
    truth = io::ReadTumTrajectory(truth_file);
    estimate = io::ReadTumTrajectory(trajectory);
  }
  if (evaluate && !in.odometry_file.empty()) {
    // The trajectory before pose-graph optimisation, for comparison.
    const eval::TrajectoryEvaluation odometry =
        eval::EvaluateTrajectory(io::ReadTumTrajectory(out / in.odometry_file), truth, {});
    Json o = Json::object();
    o["file"] = in.odometry_file;
    o["ate_rmse_m"] = odometry.metrics.ate_rmse_m;
    if (odometry.metrics.drift_percent) o["drift_percent"] = *odometry.metrics.drift_percent;
    run["odometry"] = o;
  }
  WorldFrameErrors world_errors;
  if (in.world_frame_errors && evaluate) {
    world_errors = ComputeWorldFrameErrors(estimate, truth);
  }
  if (in.world_frame_errors) {
    const bool defined = world_errors.poses > 0;
    run["position_rmse_m"] = OrNull(world_errors.position_rmse_m, defined);
    run["rotation_rmse_deg"] = OrNull(world_errors.rotation_rmse_deg, defined);
    run["position_max_error_m"] = OrNull(world_errors.position_max_error_m, defined);
    run["rotation_max_error_deg"] = OrNull(world_errors.rotation_max_error_deg, defined);
    run["error_poses"] = world_errors.poses;
  }
  eval::WriteFileAtomically(out / "run.json", JsonText(run) + "\n");

  std::cout << "scans " << in.stats.scans << " (matched " << in.stats.scans_matched << "), data "
            << summary.data_duration_s << " s in " << summary.processing_s << " s: " << summary.realtime_factor
            << "x real time, peak RSS " << summary.peak_rss_mb << " MiB\n";
  for (const auto& message : in.stats.messages) std::cout << "  note: " << message << '\n';
  if (in.stats.tracking.lost()) std::cout << "  warning: " << TrackingWarning(in.stats.tracking) << '\n';
  if (in.world_frame_errors && world_errors.poses > 0) {
    std::cout << "  position_rmse_m = " << world_errors.position_rmse_m
              << "  (unaligned: estimate and truth share the map frame)\n"
              << "  rotation_rmse_deg = " << world_errors.rotation_rmse_deg << '\n'
              << "  position_max_error_m = " << world_errors.position_max_error_m << '\n'
              << "  rotation_max_error_deg = " << world_errors.rotation_max_error_deg << '\n';
  }
  if (evaluate) {
    const eval::TrajectoryEvaluation evaluation = eval::EvaluateTrajectory(estimate, truth, {});
    // Map accuracy against the simulated world's true surfaces (map_error_*).
    eval::ReportExtras map_extras;
    const std::optional<std::filesystem::path> world = ResolveWorldFile("", truth_file);
    if (!in.map_file.empty() && world) {
      map_extras = MapReportExtras(EvaluateMapFile(
          out / in.map_file, *world, evaluation.errors.alignment.T_target_source, evaluation.errors.T_true_est_anchor));
    }
    eval::WriteEvaluationReport(evaluation, out, map_extras);
    for (const eval::MetricRow& row : eval::DescribeMetrics(evaluation.metrics)) {
      std::cout << "  " << row.key << " = " << row.value << '\n';
    }
    for (const eval::ExtraMetric& m : map_extras.metrics) {
      std::cout << "  " << m.row.key << " = " << m.row.value << '\n';
    }
  }
  WriteRunReportOrWarn(out);
  std::cout << "wrote " << trajectory.string() << ", " << (out / "run.json").string() << '\n';
  if (!summary.error.empty()) {
    std::cerr << "error: " << in.data_dir << ": " << summary.error << " (outputs hold what was processed)\n";
    return 2;
  }
  if (in.stats.scans > 0 && in.stats.scans_matched == 0 && in.stats.scans_static == 0) {
    std::cerr << "error: " << in.data_dir << ": none of the " << in.stats.scans
              << " scans was matched against the map, so the trajectory and the map hold no LiDAR "
                 "information. "
              << NoMatchAdvice(in) << '\n';
    return 3;
  }
  return 0;
}

namespace {
std::string TraceHeader() {
  return "# time_s,matched,points,points_used,points_unseen,ess,mahalanobis_sq,inflation,inlier_share,"
         "corr_x,corr_y,corr_z,corr_rx,corr_ry,corr_rz,pred_sd_x,pred_sd_y,pred_sd_z,pred_sd_rx,pred_sd_ry,"
         "pred_sd_rz,meas_sd_x,meas_sd_y,meas_sd_z,meas_sd_rx,meas_sd_ry,meas_sd_rz,vx,vy,vz,bax,bay,baz,bgx,"
         "bgy,bgz,innov_x,innov_y,innov_z,innov_rx,innov_ry,innov_rz\n";
}

std::string TraceLine(const pipeline::ScanPose& pose) {
  const pipeline::ScanDiagnostics& d = pose.diagnostics;
  char buffer[64];
  std::string line;
  const auto add = [&](double value) {
    std::snprintf(buffer, sizeof(buffer), ",%.6g", value);
    line += buffer;
  };
  std::snprintf(buffer, sizeof(buffer), "%.6f", pose.time_s);
  line += buffer;
  add(pose.matched ? 1 : 0);
  add(pose.points);
  add(d.points_used);
  add(d.points_unseen);
  add(d.effective_sample_size);
  add(d.mahalanobis_sq);
  add(d.inflation);
  add(d.inlier_share);
  for (int i = 0; i < 6; ++i) add(d.correction(i));
  for (int i = 0; i < 6; ++i) add(d.predicted_sd(i));
  for (int i = 0; i < 6; ++i) add(d.measured_sd(i));
  for (int i = 0; i < 3; ++i) add(d.velocity_m_s(i));
  for (int i = 0; i < 3; ++i) add(d.accel_bias_m_s2(i));
  for (int i = 0; i < 3; ++i) add(d.gyro_bias_rad_s(i));
  for (int i = 0; i < 6; ++i) add(d.innovation(i));
  return line + "\n";
}
}  // namespace

RunOutputsInput MakeRunOutputsInput(const std::filesystem::path& out_dir, const std::string& platform_file,
                                    const std::string& payload, const std::string& data_dir, int gpf_threads,
                                    const pipeline::RunSummary& summary, const pipeline::LocalizerStats& stats,
                                    bool has_groundtruth) {
  RunOutputsInput in;
  in.out_dir = out_dir;
  in.platform_file = platform_file;
  in.payload = payload;
  in.data_dir = data_dir;
  in.gpf_threads = static_cast<std::size_t>(gpf_threads);
  in.summary = summary;
  in.stats = stats;
  in.has_groundtruth = has_groundtruth;
  return in;
}

pipeline::RunSummary RunSinkToFolder(io::DatasetReader& reader, pipeline::EventSink& sink,
                                     const std::filesystem::path& out_dir, const std::string& trajectory_file,
                                     double max_duration_s, bool quiet, bool trace) {
  std::filesystem::create_directories(out_dir);
  io::TumTrajectoryWriter trajectory(out_dir / trajectory_file);
  pipeline::RunOptions run_options;
  std::unique_ptr<io::PartialFile> trace_file;
  if (trace) {
    trace_file = std::make_unique<io::PartialFile>(out_dir / "trace.csv");
    trace_file->Write(TraceHeader());
    run_options.on_pose = [&trace_file](const pipeline::ScanPose& pose) { trace_file->Write(TraceLine(pose)); };
  }
  run_options.max_duration_s = max_duration_s;
  run_options.stop = &SignalGuard::StopFlag();
  if (!quiet) run_options.on_progress = PrintRunProgress;
  const pipeline::RunSummary summary = pipeline::RunDataset(reader, sink, trajectory, run_options);
  if (trace_file) trace_file->Commit();
  if (!quiet) std::fprintf(stderr, "\n");
  return summary;
}

}  // namespace unimap::cli
