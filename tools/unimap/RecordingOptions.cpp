#include "RecordingOptions.hpp"

#include <cmath>
#include <iostream>
#include <map>
#include <optional>

#include "NumberChecks.hpp"
#include "io/RawInput.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {

io::ConversionOptions RecordingOptions::Resolved() const {
  io::ConversionOptions c = conversion;
  c.carmen.fov_rad = carmen_fov_deg * M_PI / 180.0;
  const std::map<std::string, io::CarmenOdometrySource> sources = {{"auto", io::CarmenOdometrySource::kAuto},
                                                                   {"odom", io::CarmenOdometrySource::kOdomLines},
                                                                   {"flaser", io::CarmenOdometrySource::kLaserFields}};
  c.carmen_odometry = sources.at(carmen_odometry);
  const std::map<std::string, io::AngleUnit> units = {
      {"", io::AngleUnit::kUnset}, {"deg", io::AngleUnit::kDegrees}, {"rad", io::AngleUnit::kRadians}};
  c.rosbag.angle_unit = units.at(angle_unit);
  return c;
}

const CLI::Option* RecordingOptions::FirstGiven() const {
  for (const CLI::Option* option : added) {
    if (option->count() > 0) return option;
  }
  return nullptr;
}

void AddRecordingOptions(CLI::App* cmd, RecordingOptions* options) {
  io::ConversionOptions& c = options->conversion;
  std::vector<CLI::Option*>& added = options->added;
  added.push_back(cmd->add_option(
      "--payload", c.payload,
      "Payload name for the dataset (default: kitti fixed_3d; carmen fixed_2d; rosbag, ros2 by the topics)"));
  added.push_back(cmd->add_option("--reorder-window-s", c.reorder_window_s,
                                  "How late (s) a message may arrive and still be put in time order")
                      ->capture_default_str()
                      ->check(CLI::NonNegativeNumber));
  // KITTI
  added.push_back(cmd->add_option("--poses", c.kitti.poses_file,
                                  "KITTI: camera-frame poses file (default: found next to the scans)"));
  added.push_back(
      cmd->add_option("--times", c.kitti.times_file, "KITTI: times.txt (default: found next to the scans)"));
  added.push_back(
      cmd->add_option("--calib", c.kitti.calib_file, "KITTI: calib.txt with Tr (default: found, else sequence 00's)"));
  // CARMEN
  added.push_back(cmd->add_option("--carmen-odometry", options->carmen_odometry,
                                  "CARMEN: odometry from ODOM lines, FLASER odom fields, or auto")
                      ->capture_default_str()
                      ->check(CLI::IsMember({"auto", "odom", "flaser"})));
  added.push_back(cmd->add_option("--carmen-fov-deg", options->carmen_fov_deg, "CARMEN: angle the FLASER beams span")
                      ->capture_default_str()
                      ->check(CLI::Range(1.0, 360.0)));
  added.push_back(
      cmd->add_option("--carmen-max-time-step-s", c.carmen.max_time_step_s,
                      "CARMEN: a message stamped more than this after the previous one is a clock jump (an error)")
          ->capture_default_str()
          ->check(FinitePositive()));
  added.push_back(cmd->add_option("--carmen-range-max-m", c.carmen.range_max_m, "CARMEN: longer ranges are no-returns")
                      ->capture_default_str()
                      ->check(CLI::PositiveNumber));
  // ROS 1 and ROS 2 bags: "" = the one topic of the type, "none" = skip.
  io::RosbagTopics& topics = c.rosbag.topics;
  added.push_back(cmd->add_option("--cloud-topic", topics.cloud,
                                  "rosbag, ros2: sensor_msgs/PointCloud2 topic (default: the only one; 'none')"));
  added.push_back(
      cmd->add_option("--laser-topic", topics.laser,
                      "rosbag, ros2: sensor_msgs/LaserScan topic (default: the only one; 'none'); rosbag: also a "
                      "custom message holding one LaserScan field"));
  added.push_back(cmd->add_option("--imu-topic", topics.imu,
                                  "rosbag, ros2: sensor_msgs/Imu topic (default: the only one; 'none')"));
  added.push_back(cmd->add_option("--joint-topic", topics.joint,
                                  "rosbag, ros2: sensor_msgs/JointState motor topic (default: the only one)"));
  added.push_back(cmd->add_option("--joint-name", c.rosbag.joint_name,
                                  "rosbag, ros2: joint whose position is the motor angle (default: first)"));
  added.push_back(cmd->add_flag(
      "--no-clock-alignment", [&c](std::int64_t) { c.clocks.align = false; },
      "rosbag, ros2: topics stamped on different clocks are an error instead of being moved onto the "
      "bag's receive clock"));
  added.push_back(cmd->add_option("--odometry-topic", topics.odometry,
                                  "rosbag, ros2: nav_msgs/Odometry topic (default: the only one; 'none')"));
  added.push_back(
      cmd->add_option("--groundtruth-topic", topics.groundtruth,
                      "rosbag, ros2: nav_msgs/Odometry or geometry_msgs/PoseStamped topic read as ground truth")
          ->capture_default_str());
  added.push_back(cmd->add_option(
      "--angle-topic", topics.angle,
      "rosbag, ros2: std_msgs Float32, Float64 or Int32 motor angle topic, stamped with the bag's receive "
      "time (default: the only one; 'none'); rosbag: with --angle-field, any message type (it may be "
      "the --laser-topic itself)"));
  added.push_back(
      cmd->add_option("--angle-field", c.rosbag.angle_field,
                      "rosbag: the --angle-topic's number field holding the motor angle (e.g. stepAngle; nested with "
                      "'.'), read by the message definition in the bag"));
  added.push_back(cmd->add_option("--angle-unit", options->angle_unit,
                                  "rosbag, ros2: unit of the --angle-topic number (required with one)")
                      ->check(CLI::IsMember({"deg", "rad"})));
}

OpenedData OpenData(const std::string& data, const RecordingOptions& recording) {
  OpenedData opened;
  const std::optional<io::RawInput> raw = io::DetectRawInput(data);
  if (!raw && recording.format.empty()) {
    if (const CLI::Option* given = recording.FirstGiven()) {
      throw InputError(given->get_name() + ": applies to a recording given as --data; " + data +
                       " is read as a dataset folder");
    }
    opened.reader = std::make_unique<io::DatasetReader>(data);
    return opened;
  }
  opened.recording_format = recording.format.empty() ? raw->format : recording.format;
  io::ConversionOptions conversion = recording.Resolved();
  conversion.input = data;
  opened.reader = std::make_unique<io::DatasetReader>(opened.recording_format, conversion);
  return opened;
}

void FinishRecording(OpenedData& data, RunOutputsInput* outputs) {
  if (data.recording_format.empty()) return;
  io::DatasetReader& reader = *data.reader;
  std::filesystem::path truth;
  if (reader.has_groundtruth()) {
    truth = outputs->out_dir / "groundtruth.tum";
    io::TumTrajectoryWriter writer(truth);
    while (const std::optional<StampedPose> pose = reader.NextGroundTruth()) writer.Write(*pose);
    writer.Close();
  }
  Json o = Json::object();
  o["format"] = data.recording_format;
  o["late_events_dropped"] = reader.late_events();
  const std::optional<io::ConversionReport> report = reader.conversion_report();
  o["complete"] = report.has_value();
  if (report) {
    o["payload"] = report->payload;
    o["scans"] = report->scans;
    o["imu"] = report->imu;
    o["encoder"] = report->encoder;
    o["odometry"] = report->odometry;
    o["groundtruth"] = report->groundtruth;
    o["dropped_points"] = report->dropped_points;
    Json skipped = Json::object();
    for (const auto& [reason, count] : report->skipped) {
      skipped[reason] = count;
      std::cout << "  recording: skipped " << count << "  " << reason << '\n';
    }
    o["skipped"] = skipped;
    o["notes"] = report->notes;
    for (const std::string& note : report->notes) std::cout << "  recording: note: " << note << '\n';
  }
  if (reader.late_events() > 0) {
    std::cout << "  recording: " << reader.late_events()
              << " items dropped: they arrived after a later item of another stream had been processed\n";
  }
  if (!truth.empty()) o["groundtruth_file"] = truth.filename().string();
  outputs->truth_file = truth;
  outputs->extras.emplace_back("recording", o);
}

}  // namespace unimap::cli
