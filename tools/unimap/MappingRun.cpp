#include "MappingRun.hpp"

#include <filesystem>
#include <iostream>
#include <optional>
#include <vector>

#include "DatasetChecks.hpp"
#include "MapOutputs.hpp"
#include "MotionChoice.hpp"
#include "OutputFolder.hpp"
#include "RunOutputs.hpp"
#include "SceneScaleReport.hpp"
#include "estimation/MotionPriorOptions.hpp"
#include "eval/LoopClosureCheck.hpp"
#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"
#include "pipeline/Mapper.hpp"
#include "pipeline/MapperSettings.hpp"
#include "pipeline/SceneScale.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

constexpr const char* kOdometryFile = "trajectory_odometry.tum";

}  // namespace

int RunMappingToFolder(const MappingRunOptions& options) {
  try {
    PrepareOutputFolder(options.out_dir, "--out");
    const Platform platform = LoadPlatform(options.platform_file);
    // The map's voxel follows the scene's scale, read from the first 3D scan
    // (docs/mapping.md, "Seventh round"); the platform's own options first,
    // so that a bad `mapper:` section is reported before the data is opened.
    const int scene_scans = pipeline::MapperOptionsFor(platform).localizer.scans_per_3d_scan;
    pipeline::SceneScale scene;
    {
      OpenedData probe = OpenData(options.data_dir, options.recording);
      scene = pipeline::ReadSceneScale(*probe.reader, scene_scans);
    }
    pipeline::MapperOptions mapper_options = pipeline::MapperOptionsFor(platform, scene);
    mapper_options.localizer.gpf.threads = options.threads;
    mapper_options.localizer.gpf.seed = options.seed;
    if (options.no_loop_closure) mapper_options.loop_search.enabled = false;
    if (options.plane_matching) mapper_options.localizer.UsePlaneMatching();
    if (options.no_line_gap_fill) mapper_options.localizer.line_gap_fill.reset();
    if (options.measure_all_line_points) mapper_options.localizer.max_predicted_distance_m = 0.0;
    OpenedData data = OpenData(options.data_dir, options.recording);
    io::DatasetReader& reader = *data.reader;
    if (!data.recording_format.empty()) {
      std::cout << "data: " << options.data_dir << " read directly as " << data.recording_format
                << " (converted as it is read, payload " << reader.metadata().payload << ")\n";
    }
    const MotionChoice motion = ChooseMotion(options.motion, reader, mapper_options.localizer.motion.static_body);
    mapper_options.localizer.motion.source = motion.source;
    std::cout << "motion: " << motion.name << " (" << motion.reason << ")\n";
    std::cout << SceneVoxelLine(platform, scene, mapper_options.submaps.map.resolution_m) << "\n";
    CheckDatasetForPlatform(reader, options.data_dir, *platform.plugin.plugin, options.force_payload);
    const std::filesystem::path out(options.out_dir);
    pipeline::Mapper mapper(mapper_options, platform.plugin.plugin);
    // The filter's own estimate streams to trajectory_odometry.tum; the
    // optimised trajectory and the map are written when the run ends.
    const pipeline::RunSummary summary =
        RunSinkToFolder(reader, mapper, out, kOdometryFile, options.max_duration_s, options.quiet, options.trace);
    MapOutputOptions map_options;
    map_options.octree_resolution_m = mapper_options.submaps.map.resolution_m;
    if (const std::vector<double>& Tr = reader.metadata().camera_from_lidar;
        Tr.size() == 12 && !platform.plugin.plugin->UsesEncoder()) {
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      for (int k = 0; k < 12; ++k) m(k / 4, k % 4) = Tr[static_cast<std::size_t>(k)];
      map_options.T_cam_lidar = Eigen::Isometry3d(m);
      map_options.T_body_lidar = platform.plugin.plugin->BodyFromLidarAt(EncoderTrack(), 0.0);
    }
    pipeline::StageTimes stages = mapper.Times();
    Json mapping = Json::object();
    {
      pipeline::StageTimer timer(&stages.outputs_s);
      mapping = WriteMapOutputs(out, mapper, map_options);
    }

    RunOutputsInput outputs =
        MakeRunOutputsInput(out, options.platform_file, platform.plugin.plugin->Name(), options.data_dir,
                            options.threads, summary, mapper.localizer_stats(), reader.has_groundtruth());
    outputs.odometry_file = kOdometryFile;
    FinishRecording(data, &outputs);
    outputs.gpf_seed = options.seed;
    outputs.map_file = "map.ply";  // (read without PCL)
    outputs.motion = motion.name;
    outputs.motion_reason = motion.reason;
    outputs.extras.emplace_back("mapping", mapping);
    outputs.extras.emplace_back("scene_scale",
                                SceneScaleJson(platform, scene, mapper_options.submaps.map.resolution_m));
    outputs.extras.emplace_back("stages", StageTimesJson(stages, summary.processing_s, !options.quiet));
    const pipeline::MapperStats stats = mapper.stats();
    if (outputs.has_groundtruth && stats.first_loop_closure_time_s >= 0.0) {
      const std::filesystem::path truth = outputs.TruthFile();
      const std::optional<LoopPointErrors> loop_point =
          ComputeLoopPointErrors(io::ReadTumTrajectory(out / kOdometryFile), mapper.OptimizedTrajectory(),
                                 io::ReadTumTrajectory(truth), stats.first_loop_closure_time_s);
      if (loop_point) outputs.extras.emplace_back("loop_point", LoopPointJson(*loop_point));
      std::vector<eval::ClaimedMotion> claims;
      for (const pipeline::LoopClosureLink& link : mapper.LoopClosureLinks()) {
        claims.push_back({link.submap_start_time_s, link.time_s, link.T_start_body});
      }
      const eval::LoopClosureCheck check = eval::CheckLoopClosures(claims, io::ReadTumTrajectory(truth));
      Json o = Json::object();
      o["checked"] = check.checked;
      o["false_closures"] = check.false_closures;
      o["max_translation_error_m"] = check.max_translation_error_m;
      o["max_rotation_error_deg"] = check.max_rotation_error_deg;
      o["false_translation_m"] = check.false_translation_m;
      o["false_rotation_deg"] = check.false_rotation_deg;
      Json list = Json::array();
      for (const eval::FalseClosure& f : check.false_list) {
        const Eigen::Vector3d& e = f.translation_error_m;
        list.push_back({{"submap_start_time_s", f.start_time_s},
                        {"time_s", f.end_time_s},
                        {"translation_error_start_frame_m", {e.x(), e.y(), e.z()}},
                        {"rotation_error_deg", f.rotation_error_deg}});
      }
      o["false"] = list;
      outputs.extras.emplace_back("loop_closure_check", o);
      if (check.false_closures > 0) {
        std::cout << "  note: " << check.false_closures << " of " << check.checked
                  << " loop closures are false by the ground truth (off by more than " << check.false_translation_m
                  << " m or " << check.false_rotation_deg << " deg)\n";
      }
    }
    std::cout << "mapping: " << stats.key_scans << " 3D scans, " << stats.submaps << " submaps, " << stats.loop_closures
              << " loop closures, " << stats.optimizations << " optimisations\n";
    return WriteRunOutputs(outputs);
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace unimap::cli
