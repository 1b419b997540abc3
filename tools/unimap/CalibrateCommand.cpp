// `unimap calibrate`: the LiDAR extrinsic of a rig from the agreement of its
// own map's views (docs/calibration.md); writes a platform file with it.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "CalibrationInput.hpp"
#include "Commands.hpp"
#include "NumberChecks.hpp"
#include "RecordingOptions.hpp"
#include "calibration/ExtrinsicCalibrator.hpp"
#include "config/PlatformFileWriter.hpp"
#include "eval/AtomicFile.hpp"
#include "eval/MapQuality.hpp"
#include "io/PlyWriter.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Extrinsic.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

struct CalibrateOptions {
  std::string platform_file;
  std::string data;
  std::string out_file;
  std::string trajectory_file;
  std::string maps_dir;
  bool static_body = false;
  double max_duration_s = 0.0;
  calibration::CalibrationOptions calibration;
  RecordingOptions recording;
};

// The platform's LiDAR extrinsic key: the last transform of its chain to the
// LiDAR (T_motor_lidar on a motor, else T_body_lidar).
std::string ExtrinsicKey(const Platform& platform) {
  for (const char* key : {"extrinsic.motor_lidar", "extrinsic.body_lidar"}) {
    if (platform.parameters.Contains(std::string(key) + ".translation_m")) return key;
  }
  throw InputError(platform.file + ": the payload '" + platform.plugin_name +
                   "' has no extrinsic.motor_lidar or extrinsic.body_lidar parameters to calibrate");
}

Extrinsic FromIsometry(const Eigen::Isometry3d& T) {
  Extrinsic e;
  e.translation_m = T.translation();
  const Eigen::Vector3d ypr = T.linear().eulerAngles(2, 1, 0);  // R = Rz(yaw) Ry(pitch) Rx(roll)
  e.rpy_deg = Eigen::Vector3d(ypr(2), ypr(1), ypr(0)) * kRadToDeg;
  for (int a = 0; a < 3; ++a) {  // the equivalent angles nearest zero
    if (e.rpy_deg(a) > 180.0) e.rpy_deg(a) -= 360.0;
  }
  if (std::abs(e.rpy_deg(0)) > 90.0 + 1e-9 && std::abs(e.rpy_deg(2)) > 90.0 + 1e-9) {
    // (roll, pitch, yaw) and (roll - 180, 180 - pitch, yaw - 180) are the same rotation.
    e.rpy_deg = Eigen::Vector3d(e.rpy_deg(0) - std::copysign(180.0, e.rpy_deg(0)),
                                std::copysign(180.0, e.rpy_deg(1)) - e.rpy_deg(1),
                                e.rpy_deg(2) - std::copysign(180.0, e.rpy_deg(2)));
  }
  return e;
}

std::string Vec(const Eigen::Vector3d& v, double scale, int digits) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << '[' << v.x() * scale << ", " << v.y() * scale << ", " << v.z() * scale
    << ']';
  return o.str();
}

int RunCalibrate(const CalibrateOptions& options) {
  try {
    if (options.trajectory_file.empty() == !options.static_body) {
      throw InputError(
          "give either --static (the body stood still: a scanner on a stand) or --trajectory FILE (the body's "
          "poses, e.g. trajectory.tum of a `unimap run` of the same data)");
    }
    const Platform platform = LoadPlatform(options.platform_file);
    const std::string key = ExtrinsicKey(platform);
    const std::vector<StampedPose> trajectory =
        options.trajectory_file.empty() ? std::vector<StampedPose>{} : io::ReadTumTrajectory(options.trajectory_file);
    OpenedData data = OpenData(options.data, options.recording);
    const CalibrationInput input =
        ReadCalibrationInput(*data.reader, *platform.plugin.plugin, trajectory, options.max_duration_s);
    std::cout << "data: " << input.scans << " scans (" << input.scans_used << " placed, " << input.returns.size()
              << " returns), " << input.encoder_samples << " encoder samples; body "
              << (options.static_body ? "standing still" : "at the poses of " + options.trajectory_file) << '\n';
    if (input.scans_outside > 0) {
      std::cout << "  skipped: " << input.scans_outside << " scans (first: " << input.first_skip << ")\n";
    }
    const calibration::CalibrationResult r =
        calibration::ExtrinsicCalibrator(options.calibration).Calibrate(input.returns);
    const auto write_map = [&](const char* name, const std::vector<Eigen::Vector3f>& map) {
      if (options.maps_dir.empty()) return;
      std::filesystem::create_directories(options.maps_dir);
      const std::filesystem::path file = std::filesystem::path(options.maps_dir) / name;
      io::WritePly(file, map);
      std::cout << "wrote " << file.string() << '\n';
    };
    const std::vector<Eigen::Vector3f> uncalibrated =
        calibration::ExtrinsicCalibrator::Assemble(input.returns, Eigen::Isometry3d::Identity());
    write_map("uncalibrated.ply", uncalibrated);
    if (!r.ok) {
      std::cerr << "error: " << options.data << ": cannot calibrate: " << r.failure << '\n';
      return 1;
    }
    const std::vector<Eigen::Vector3f> calibrated =
        calibration::ExtrinsicCalibrator::Assemble(input.returns, r.T_lidar_corrected);
    const Extrinsic before = Extrinsic::FromMap(platform.parameters, key);
    const Extrinsic after = FromIsometry(before.ToIsometry() * r.T_lidar_corrected);
    eval::MapQualityOptions quality;  // (an even subset: the measure's cost grows with the points evaluated)
    quality.max_points = 20000;
    const eval::MapQuality q0 = eval::ComputeMapQuality(uncalibrated, quality);
    const eval::MapQuality q1 = eval::ComputeMapQuality(calibrated, quality);
    const Eigen::Matrix<double, 6, 1> sd = r.covariance.diagonal().cwiseSqrt();
    std::ostringstream report;
    report << "calibrated by `unimap calibrate` from " << options.data << " (" << input.returns.size() << " returns, "
           << r.neighbourhoods << " planes seen from two views)\n"
           << key << ": translation_m " << Vec(before.translation_m, 1, 4) << " -> " << Vec(after.translation_m, 1, 4)
           << ", rpy_deg " << Vec(before.rpy_deg, 1, 3) << " -> " << Vec(after.rpy_deg, 1, 3) << '\n'
           << "directions estimated: " << r.observable << " of 6 (the others keep the platform's values)\n"
           << "standard deviation (LiDAR frame): translation_mm " << Vec(sd.head<3>(), 1000, 1) << ", rotation_deg "
           << Vec(sd.tail<3>(), kRadToDeg, 3) << '\n'
           << "distance between the views' surfaces (RMS): " << std::setprecision(4) << r.rms_start_m * 1000 << " -> "
           << r.rms_end_m * 1000 << " mm; mean plane variance " << q0.mean_plane_variance_m2 << " -> "
           << q1.mean_plane_variance_m2 << " m^2, mean map entropy " << q0.mean_map_entropy << " -> "
           << q1.mean_map_entropy << (r.converged ? "" : "\n(not converged: the last round still moved it)");
    std::cout << report.str() << '\n';
    for (int k = 0; k < 6; ++k) {
      if (r.information_ratio(k) >= options.calibration.min_information_ratio) continue;
      const auto d = r.directions.col(k);
      std::cout << "  not estimated: direction [translation " << Vec(d.head<3>(), 1, 3) << ", rotation "
                << Vec(d.tail<3>(), 1, 3) << "] (in units of the prior's "
                << options.calibration.prior_sigma_translation_m << " m and "
                << options.calibration.prior_sigma_rotation_deg << " deg; information " << std::setprecision(3)
                << r.information_ratio(k) << " x the prior's)\n";
    }
    // The platform file again, with the calibrated extrinsic.
    std::vector<ParameterOverride> parameters;
    for (const EffectiveParameter& p : platform.effective) {
      if (p.source != ParameterSource::kPlatformFile || p.spec.key.rfind(key + ".", 0) == 0) continue;
      parameters.push_back({p.spec.key, p.value, p.line});
    }
    const auto list = [](const Eigen::Vector3d& v) { return std::vector<double>{v.x(), v.y(), v.z()}; };
    parameters.push_back({key + ".translation_m", list(after.translation_m), 0});
    parameters.push_back({key + ".rpy_deg", list(after.rpy_deg), 0});
    eval::WriteFileAtomically(
        options.out_file, WritePlatformYaml(platform.plugin_name, parameters, platform.mapper_settings, report.str()));
    std::cout << "wrote " << options.out_file << '\n';
    write_map("calibrated.ply", calibrated);
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddCalibrateCommand(CLI::App* app) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app->add_subcommand(
      "calibrate",
      "Estimate the LiDAR extrinsic (T_motor_lidar, or T_body_lidar) from how the map's views agree; write a "
      "platform file with it (docs/calibration.md)");
  cmd->add_option("--platform", options->platform_file, "Platform YAML (its extrinsic is the start)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--data", options->data, "Dataset folder or recording, as for `unimap run`")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--out", options->out_file, "Platform YAML to write")->required();
  cmd->add_option("--trajectory", options->trajectory_file,
                  "The body's poses (TUM), e.g. trajectory.tum of a `unimap run` of the same data")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--static", options->static_body, "The body stood still (a scanner on a stand)");
  cmd->add_option("--maps-out", options->maps_dir,
                  "Also write every return placed with the platform's extrinsic (DIR/uncalibrated.ply) and with the "
                  "calibrated one (DIR/calibrated.ply), to compare in a viewer");
  cmd->add_option("--max-duration-s", options->max_duration_s, "Use only this much data (s)")->check(FinitePositive());
  cmd->add_option("--sigma-m", options->calibration.sigma_m, "The returns' noise across a surface (m)")
      ->check(FinitePositive())
      ->capture_default_str();
  cmd->add_option("--radius-m", options->calibration.neighbourhood_radius_m, "Neighbourhood radius (m)")
      ->check(FinitePositive())
      ->capture_default_str();
  cmd->add_option("--format", options->recording.format, "The --data recording's format (default: detected)")
      ->check(CLI::IsMember({"kitti", "carmen", "rosbag", "ros2"}));
  AddRecordingOptions(cmd, &options->recording);
  cmd->callback([options]() {
    const int code = RunCalibrate(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
