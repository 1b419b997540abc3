// `unimap localize`: track the pose of a dataset in a fixed prior map (an
// OctoMap .bt or a .pcd point cloud), write the trajectory, run.json and,
// with ground truth, the evaluation (estimate and truth share the map frame).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "DatasetChecks.hpp"
#include "MapEvaluation.hpp"
#include "NumberChecks.hpp"
#include "OutputFolder.hpp"
#include "RecordingOptions.hpp"
#include "RunOutputs.hpp"
#include "SignalGuard.hpp"
#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"
#include "map/DistanceMap.hpp"
#include "map/WholeMapOptions.hpp"
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Localizer.hpp"
#include "pipeline/MapperSettings.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

struct LocalizeCliOptions {
  std::string map_file;           // prior map: .bt (OctoMap) or .pcd (points)
  std::string platform_file;      // platform YAML
  std::string data_dir;           // dataset folder, or a recording read directly
  RecordingOptions recording;     // how to read a recording given as data_dir
  std::string out_dir;            // output folder
  std::string initial_pose;       // "x y z qx qy qz qw" (T_map_body), empty: from the truth or identity
  std::string initial_attitude;   // "pose" or "gravity"; empty: pose for a ground-truth start, else gravity
  double map_resolution_m = 0.0;  // distance-map voxel (m); 0: ForPriorMap's (platform's, at most 0.1)
  double max_duration_s = 0.0;    // 0: the whole dataset
  bool point_to_plane = false;    // points measured against their nearest surface plane (GpfOptions)
  int threads = 1;                // GPF threads
  bool quiet = false;             // no progress line
  bool trace = false;             // also write trace.csv (as unimap run --trace)
  bool force_payload = false;     // run a dataset recorded for another payload (else an error)
};

// The initial T_map_body and where it came from.
struct InitialPose {
  Eigen::Isometry3d T_map_body = Eigen::Isometry3d::Identity();  // also the map box's first centre
  std::string source;                                            // "option", "groundtruth" or "identity"
  // False for "identity": the localiser's default start is used instead
  // (origin, yaw 0, roll and pitch from gravity alignment).
  bool given = true;
};

// "x y z qx qy qz qw" (spaces or commas) -> pose; the quaternion is
// normalised. Throws InputError for anything else.
Eigen::Isometry3d ParsePose(const std::string& text) {
  std::string spaced = text;
  for (char& c : spaced) {
    if (c == ',') c = ' ';
  }
  std::istringstream in(spaced);
  std::vector<double> v;
  std::string token;
  while (in >> token) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(token, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != token.size() || !std::isfinite(value)) {
      throw InputError("--initial-pose: '" + token + "' is not a finite number");
    }
    v.push_back(value);
  }
  if (v.size() != 7) {
    throw InputError("--initial-pose: expected 7 numbers \"x y z qx qy qz qw\", got " + std::to_string(v.size()));
  }
  const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
  if (!(q.norm() > 1e-6)) throw InputError("--initial-pose: the quaternion is zero");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  return T;
}

std::string PoseText(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  std::ostringstream out;
  out.precision(6);
  out << T.translation().x() << ' ' << T.translation().y() << ' ' << T.translation().z() << ' ' << q.x() << ' ' << q.y()
      << ' ' << q.z() << ' ' << q.w();
  return out.str();
}

InitialPose ChooseInitialPose(const LocalizeCliOptions& options, const OpenedData& data) {
  if (!options.initial_pose.empty()) return {ParsePose(options.initial_pose), "option"};
  // (A recording read directly: its ground truth is not read ahead of its scans.)
  if (data.recording_format.empty() && data.reader->has_groundtruth()) {
    const auto truth = io::ReadTumTrajectory(std::filesystem::path(options.data_dir) / "groundtruth.tum");
    if (!truth.empty()) return {truth.front().T_map_body, "groundtruth"};
  }
  return {Eigen::Isometry3d::Identity(), "identity", false};
}

// The map's file exists and has a supported extension; throws InputError naming it otherwise.
void CheckMapFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError("map '" + file.string() + "': no such file");
  const std::string ext = file.extension().string();
  if (ext != ".bt" && ext != ".pcd") {
    throw InputError("map '" + file.string() + "': unsupported format '" + ext + "' (expected .bt or .pcd)");
  }
}

// The prior map, boxed around center_map (*whole_map: one fixed box holds all
// of it); throws InputError naming the file.
std::unique_ptr<map::DistanceMap> LoadMap(const std::filesystem::path& file, const map::DistanceMapOptions& options,
                                          const Eigen::Vector3f& center_map, std::size_t* points, bool* whole_map) {
  CheckMapFile(file);
  *whole_map = false;
  if (file.extension() == ".bt") {
    *points = 0;
    return map::DistanceMap::LoadBt(file, options, center_map);
  }
  std::vector<Eigen::Vector3f> points_map = LoadMapPoints(file);
  points_map.erase(
      std::remove_if(points_map.begin(), points_map.end(), [](const Eigen::Vector3f& p) { return !p.allFinite(); }),
      points_map.end());
  if (points_map.empty()) throw InputError("map '" + file.string() + "': no finite points");
  *points = points_map.size();
  // A map that fits the cell budget gets one fixed distance box, computed
  // once (rotating Hokuyo, 60 s of tunnel: real-time factor 0.73 with a box
  // that follows the sensor and is recomputed on every recentring).
  const std::optional<map::DistanceMapOptions> whole = map::WholeMapOptions(points_map, options, center_map);
  *whole_map = whole.has_value();
  return map::DistanceMap::FromPoints(points_map, whole.value_or(options), center_map);
}

int RunLocalize(const LocalizeCliOptions& options) {
  try {
    // Cheap checks of the arguments first, before the platform and the data are loaded.
    CheckMapFile(options.map_file);
    if (!options.initial_pose.empty()) ParsePose(options.initial_pose);
    PrepareOutputFolder(options.out_dir, "--out");
    const Platform platform = LoadPlatform(options.platform_file);
    pipeline::LocalizerOptions localizer_options = pipeline::PriorMapOptionsFor(platform);
    localizer_options.gpf.threads = options.threads;
    localizer_options.gpf.point_to_plane = options.point_to_plane;
    localizer_options.map.cell_planes = options.point_to_plane;  // the planes it ties points to
    const bool bt_map = std::filesystem::path(options.map_file).extension() == ".bt";
    if (options.map_resolution_m > 0.0) {
      if (bt_map) throw InputError("--map-resolution-m: applies to .pcd maps; a .bt map keeps its own resolution");
      localizer_options.map.resolution_m = options.map_resolution_m;
    }
    const bool clamp_set = std::any_of(platform.mapper_settings.begin(), platform.mapper_settings.end(),
                                       [](const ParameterOverride& s) { return s.key == "map.clamp_distance_m"; });
    if (!bt_map && !clamp_set) {
      // The particle filter clamps distances at its own clamp, so a field
      // clamped there too changes only lookups whose trilinear stencil
      // reaches past it, and lets a whole tunnel fit one box (WholeMapOptions).
      // (.bt maps keep the default clamp: their resolution is the file's.)
      localizer_options.ClampFieldAtLikelihood();
    }
    OpenedData data = OpenData(options.data_dir, options.recording);
    io::DatasetReader& reader = *data.reader;
    CheckDatasetForPlatform(reader, options.data_dir, *platform.plugin.plugin, options.force_payload);
    const InitialPose initial = ChooseInitialPose(options, data);
    const std::string attitude = !options.initial_attitude.empty() ? options.initial_attitude
                                 : initial.source == "groundtruth" ? "pose"
                                                                   : "gravity";
    localizer_options.initial_attitude = attitude == "pose" ? pipeline::LocalizerOptions::InitialAttitude::kPose
                                                            : pipeline::LocalizerOptions::InitialAttitude::kGravity;
    std::cout << "initial pose (" << initial.source << "): " << PoseText(initial.T_map_body);
    if (!initial.given) {
      std::cout << ", roll and pitch from gravity (no --initial-pose, no ground truth)\n";
    } else if (attitude == "pose") {
      std::cout << ", attitude: pose (accelerometer bias from the static start)\n";
    } else {
      std::cout << ", attitude: gravity (heading from the pose)\n";
    }

    std::size_t map_points = 0;
    bool whole_map = false;
    std::unique_ptr<map::DistanceMap> prior =
        LoadMap(options.map_file, localizer_options.map, initial.T_map_body.translation().cast<float>(), &map_points,
                &whole_map);
    prior->WaitForUpdates();  // the first distance field is ready before the first scan
    std::cout << "map " << options.map_file;
    if (map_points > 0) std::cout << ": " << map_points << " points";
    const double map_resolution_m = prior->options().resolution_m;
    localizer_options.gpf.voxel_size_m = map_resolution_m;  // scans downsampled at the loaded map's voxel
    std::cout << ", resolution " << map_resolution_m << " m, "
              << (whole_map ? "one distance box for the whole map" : "distance box following the sensor") << '\n';

    const std::filesystem::path out(options.out_dir);
    pipeline::Localizer localizer(localizer_options, platform.plugin.plugin, std::move(prior),
                                  initial.given ? std::optional<Eigen::Isometry3d>(initial.T_map_body) : std::nullopt);
    const pipeline::RunSummary summary =
        RunSinkToFolder(reader, localizer, out, "trajectory.tum", options.max_duration_s, options.quiet, options.trace);

    RunOutputsInput outputs =
        MakeRunOutputsInput(out, options.platform_file, platform.plugin.plugin->Name(), options.data_dir,
                            options.threads, summary, localizer.stats(), reader.has_groundtruth());
    outputs.world_frame_errors = true;
    FinishRecording(data, &outputs);
    Json extra = Json::object();
    extra["map"] = options.map_file;
    extra["map_points"] = map_points;
    extra["map_resolution_m"] = map_resolution_m;
    extra["map_whole_box"] = whole_map;
    extra["initial_pose_source"] = initial.source;
    extra["initial_pose"] = PoseText(initial.T_map_body);
    // The attitude source used (a requested "pose" falls back to "gravity"
    // when the pose's tilt disagrees with gravity; see the messages).
    const std::optional<estimation::InitialAttitude> used = localizer.stats().initial_attitude;
    extra["initial_attitude"] = std::string(used && *used == estimation::InitialAttitude::kPose ? "pose" : "gravity");
    if (initial.given) extra["initial_attitude_requested"] = attitude;
    outputs.extras.emplace_back("localize", extra);
    return WriteRunOutputs(outputs);
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddLocalizeCommand(CLI::App* app) {
  auto options = std::make_shared<LocalizeCliOptions>();
  CLI::App* cmd =
      app->add_subcommand("localize", "Localise a dataset in a fixed prior map (.bt or .pcd) and evaluate it");
  cmd->add_option("--map", options->map_file, "Prior map: OctoMap .bt or point cloud .pcd (map frame)")->required();
  cmd->add_option("--platform", options->platform_file, "Platform YAML")->required()->check(CLI::ExistingFile);
  cmd->add_option("--data", options->data_dir,
                  "Dataset folder (docs/dataset-format.md), or a recording read directly (as `unimap run`)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--format", options->recording.format,
                  "The --data recording's format (default: detected; convert's --format)")
      ->check(CLI::IsMember({"kitti", "carmen", "rosbag", "ros2"}));
  AddRecordingOptions(cmd, &options->recording);
  cmd->add_option("--out", options->out_dir, "Output folder")->required();
  cmd->add_option("--initial-pose", options->initial_pose,
                  "T_map_body at the end of the static start, \"x y z qx qy qz qw\" "
                  "(default: the dataset's first ground-truth pose, else identity)");
  cmd->add_option("--initial-attitude", options->initial_attitude,
                  "With an initial pose: 'pose' takes its roll and pitch and estimates the accelerometer bias "
                  "from the static start; 'gravity' takes roll and pitch from gravity (default: pose for a "
                  "ground-truth start, gravity for --initial-pose)")
      ->check(CLI::IsMember({"pose", "gravity"}));
  cmd->add_option("--map-resolution-m", options->map_resolution_m,
                  "Distance-map voxel edge (m) for a .pcd prior map (a .bt map keeps its own), also the "
                  "scan's downsampling voxel (default: the platform's distance_map_resolution_m, at most 0.1)")
      ->check(CLI::Range(0.01, 2.0));
  cmd->add_option("--max-duration-s", options->max_duration_s, "Process only this much data (s)")
      ->check(FinitePositive());
  cmd->add_flag("--force-payload", options->force_payload,
                "Run a dataset recorded for another payload than the platform's (an error otherwise)");
  cmd->add_flag("--point-to-plane", options->point_to_plane,
                "Measure each scan point against the plane of the map surface nearest to it at the prediction "
                "instead of the distance field (helps in maps that hold only part of a surface; "
                "docs/localization.md)");
  cmd->add_option("--threads", options->threads, "Threads for particle weighting")->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", options->quiet, "No progress line");
  cmd->add_flag("--trace", options->trace,
                "Also write trace.csv, as unimap run --trace: per scan, how the pose was found in the prior map");
  cmd->callback([options]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: stop, write what was processed, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunLocalize(*options));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
