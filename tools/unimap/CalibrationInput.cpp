#include "CalibrationInput.hpp"

#include <algorithm>
#include <deque>
#include <optional>
#include <utility>
#include <variant>

#include "eval/TrajectoryAssociation.hpp"
#include "io/ScanRecord.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/Errors.hpp"
#include "unimap/LineScan.hpp"

namespace unimap::cli {
namespace {

// T_world_body at time_s from a time-ordered trajectory; nullopt outside it.
std::optional<Eigen::Isometry3d> BodyPoseAt(const std::vector<StampedPose>& trajectory, double time_s) {
  if (trajectory.empty()) return Eigen::Isometry3d::Identity();
  if (time_s < trajectory.front().time_s || time_s > trajectory.back().time_s) return std::nullopt;
  const auto after = std::lower_bound(trajectory.begin(), trajectory.end(), time_s,
                                      [](const StampedPose& p, double t) { return p.time_s < t; });
  if (after == trajectory.begin()) return trajectory.front().T_map_body;
  return eval::InterpolatePose(*(after - 1), *after, time_s);
}

}  // namespace

CalibrationInput ReadCalibrationInput(io::DatasetReader& reader, const PayloadPlugin& plugin,
                                      const std::vector<StampedPose>& trajectory, double max_duration_s) {
  CalibrationInput input;
  EncoderTrack encoder;
  const MotionQuery at_rest = [](double) { return Eigen::Isometry3d::Identity(); };
  // Scans wait here until the encoder covers them (a scan needs the samples
  // around its last firing), then are placed and dropped: only the returns
  // are kept.
  std::deque<std::pair<std::uint32_t, RawScan>> pending;
  const auto place = [&](std::uint32_t index, const RawScan& scan) {
    try {
      const BodyScan body = plugin.Deskew(scan, encoder, at_rest);
      std::vector<calibration::CalibrationReturn> placed;
      placed.reserve(body.points.size());
      for (const Point& point : body.points) {
        const std::optional<Eigen::Isometry3d> T_world_body = BodyPoseAt(trajectory, point.time_s);
        if (!T_world_body)
          throw InputError("a return at " + std::to_string(point.time_s) + " s is outside the trajectory");
        const Eigen::Isometry3d T_body_lidar = plugin.BodyFromLidarAt(encoder, point.time_s);
        const Eigen::Isometry3d T_world_lidar = *T_world_body * T_body_lidar;
        calibration::CalibrationReturn r;
        r.p_lidar = (T_body_lidar.inverse() * point.position_m).cast<float>();
        r.q_world_lidar = Eigen::Quaterniond(T_world_lidar.linear()).cast<float>();
        r.t_world_lidar = T_world_lidar.translation().cast<float>();
        r.scan = index;
        placed.push_back(r);
      }
      input.returns.insert(input.returns.end(), placed.begin(), placed.end());
      ++input.scans_used;
    } catch (const InputError& e) {
      if (input.first_skip.empty()) input.first_skip = "scan " + std::to_string(index) + ": " + e.what();
      ++input.scans_outside;
    }
  };
  const auto place_covered = [&] {
    while (!pending.empty() &&
           (!plugin.UsesEncoder() || (!encoder.empty() && encoder.end_time_s() > pending.front().second.end_time_s))) {
      place(pending.front().first, pending.front().second);
      pending.pop_front();
    }
  };
  double first_end = 0.0;
  while (const std::optional<io::DatasetEvent> event = reader.NextEvent()) {
    if (const auto* sample = std::get_if<EncoderSample>(&*event)) {
      encoder.Append(*sample);
      ++input.encoder_samples;
      place_covered();
      continue;
    }
    const auto* record = std::get_if<io::ScanRecord>(&*event);
    if (record == nullptr) continue;
    const double end = io::ScanEndTime(*record);
    if (input.scans == 0) first_end = end;
    if (max_duration_s > 0.0 && end - first_end > max_duration_s) break;
    const auto index = static_cast<std::uint32_t>(input.scans++);
    if (const auto* line = std::get_if<LineScan>(record)) {
      pending.emplace_back(index, LineScanToRawScan(*line).scan);
    } else {
      pending.emplace_back(index, std::get<RawScan>(*record));
    }
    place_covered();
  }
  for (const auto& [index, scan] : pending) place(index, scan);  // the encoder ends before them: skipped
  return input;
}

}  // namespace unimap::cli
