#include "CalibrationInput.hpp"

#include <algorithm>
#include <optional>
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
  std::vector<RawScan> scans;
  EncoderTrack encoder;
  double first_end = 0.0;
  while (const std::optional<io::DatasetEvent> event = reader.NextEvent()) {
    if (const auto* sample = std::get_if<EncoderSample>(&*event)) {
      encoder.Append(*sample);
      ++input.encoder_samples;
      continue;
    }
    const auto* record = std::get_if<io::ScanRecord>(&*event);
    if (record == nullptr) continue;
    const double end = io::ScanEndTime(*record);
    if (input.scans == 0) first_end = end;
    if (max_duration_s > 0.0 && end - first_end > max_duration_s) break;
    ++input.scans;
    if (const auto* line = std::get_if<LineScan>(record)) {
      scans.push_back(LineScanToRawScan(*line).scan);
    } else {
      scans.push_back(std::get<RawScan>(*record));
    }
  }
  const MotionQuery at_rest = [](double) { return Eigen::Isometry3d::Identity(); };
  for (std::size_t k = 0; k < scans.size(); ++k) {
    try {
      const BodyScan body = plugin.Deskew(scans[k], encoder, at_rest);
      std::vector<calibration::CalibrationReturn> placed;
      placed.reserve(body.points.size());
      for (const Point& point : body.points) {
        const std::optional<Eigen::Isometry3d> T_world_body = BodyPoseAt(trajectory, point.time_s);
        if (!T_world_body) throw InputError("a return at " + std::to_string(point.time_s) + " s is outside the trajectory");
        const Eigen::Isometry3d T_body_lidar = plugin.BodyFromLidarAt(encoder, point.time_s);
        const Eigen::Isometry3d T_world_lidar = *T_world_body * T_body_lidar;
        calibration::CalibrationReturn r;
        r.p_lidar = (T_body_lidar.inverse() * point.position_m).cast<float>();
        r.q_world_lidar = Eigen::Quaterniond(T_world_lidar.linear()).cast<float>();
        r.t_world_lidar = T_world_lidar.translation().cast<float>();
        r.scan = static_cast<std::uint32_t>(k);
        placed.push_back(r);
      }
      input.returns.insert(input.returns.end(), placed.begin(), placed.end());
      ++input.scans_used;
    } catch (const InputError& e) {
      if (input.first_skip.empty()) input.first_skip = "scan " + std::to_string(k) + ": " + e.what();
      ++input.scans_outside;
    }
  }
  return input;
}

}  // namespace unimap::cli
