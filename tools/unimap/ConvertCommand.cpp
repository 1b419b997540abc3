// `unimap convert`: KITTI, CARMEN, ROS 1 and ROS 2 bag data into the dataset format.
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "NumberChecks.hpp"
#include "OutputFolder.hpp"
#include "SignalGuard.hpp"
#include "io/DatasetConversion.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

struct ConvertOptions {
  io::ConversionOptions conversion;      // input, output, payload and per-format options
  std::string format;                    // kitti | carmen | rosbag | ros2
  std::string carmen_odometry = "auto";  // auto | odom | flaser
  double carmen_fov_deg = 180.0;         // FLASER beams span
  std::string angle_unit;                // angle topic's number: deg | rad; "" = not given
};

void PrintReport(const std::string& format, const io::ConversionReport& report, std::ostream& out) {
  out << "converted " << format << " -> payload " << report.payload << '\n'
      << "  scans:        " << report.scans << '\n'
      << "  imu:          " << report.imu << '\n'
      << "  encoder:      " << report.encoder << '\n'
      << "  odometry:     " << report.odometry << '\n'
      << "  ground truth: " << report.groundtruth << '\n';
  if (report.dropped_points > 0) out << "  points dropped (non-finite): " << report.dropped_points << '\n';
  if (!report.skipped.empty()) {
    out << "  skipped:\n";
    for (const auto& [reason, count] : report.skipped) out << "    " << count << "  " << reason << '\n';
  }
  for (const std::string& note : report.notes) out << "  note: " << note << '\n';
}

int RunConvert(ConvertOptions options) {
  try {
    io::ConversionOptions& c = options.conversion;
    c.stop = &SignalGuard::StopFlag();
    PrepareOutputFolder(c.output, "--out");
    io::ConversionReport report;
    if (options.format == "kitti") {
      report = io::ConvertKitti(c);
    } else if (options.format == "carmen") {
      c.carmen.fov_rad = options.carmen_fov_deg * M_PI / 180.0;
      const std::map<std::string, io::CarmenOdometrySource> sources = {
          {"auto", io::CarmenOdometrySource::kAuto},
          {"odom", io::CarmenOdometrySource::kOdomLines},
          {"flaser", io::CarmenOdometrySource::kLaserFields}};
      c.carmen_odometry = sources.at(options.carmen_odometry);
      report = io::ConvertCarmen(c);
    } else {
      const std::map<std::string, io::AngleUnit> units = {
          {"", io::AngleUnit::kUnset}, {"deg", io::AngleUnit::kDegrees}, {"rad", io::AngleUnit::kRadians}};
      c.rosbag.angle_unit = units.at(options.angle_unit);
      report = options.format == "rosbag" ? io::ConvertRosbag(c) : io::ConvertRos2Bag(c);
    }
    PrintReport(options.format, report, std::cout);
    if (report.interrupted) {
      std::cout << "interrupted (signal " << SignalGuard::Received()
                << "): the dataset holds the messages read before, complete\n";
    }
    std::cout << "wrote " << c.output.string() << '\n';
    if (report.scans == 0 && !report.interrupted) {
      // An empty conversion is no success: nothing in it can be mapped.
      std::cerr << "error: " << c.input.string() << ": no scan converted: the dataset written holds none"
                << " (see the counts and notes above)\n";
      return 2;
    }
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {  // e.g. std::filesystem errors on the output folder
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddConvertCommand(CLI::App* app) {
  auto options = std::make_shared<ConvertOptions>();
  io::ConversionOptions& c = options->conversion;
  CLI::App* cmd =
      app->add_subcommand("convert", "Convert KITTI, CARMEN, ROS 1 or ROS 2 bag data into a unimap dataset folder");
  cmd->add_option("--input", c.input,
                  "KITTI sequence folder, CARMEN log (.clf, .clf.bz2), ROS 1 bag, or ROS 2 bag folder (or .db3)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--format", options->format, "Input format")
      ->required()
      ->check(CLI::IsMember({"kitti", "carmen", "rosbag", "ros2"}));
  cmd->add_option("--out", c.output, "Dataset folder to write")->required();
  cmd->add_option(
      "--payload", c.payload,
      "Payload name for metadata.yaml (default: kitti fixed_3d; carmen fixed_2d; rosbag, ros2 by the topics)");
  cmd->add_option("--reorder-window-s", c.reorder_window_s,
                  "How late (s) a message may arrive and still be put in time order")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  // KITTI
  cmd->add_option("--poses", c.kitti.poses_file, "KITTI: camera-frame poses file (default: found next to the scans)");
  cmd->add_option("--times", c.kitti.times_file, "KITTI: times.txt (default: found next to the scans)");
  cmd->add_option("--calib", c.kitti.calib_file, "KITTI: calib.txt with Tr (default: found, else sequence 00's)");
  // CARMEN
  cmd->add_option("--carmen-odometry", options->carmen_odometry,
                  "CARMEN: odometry from ODOM lines, FLASER odom fields, or auto")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "odom", "flaser"}));
  cmd->add_option("--carmen-fov-deg", options->carmen_fov_deg, "CARMEN: angle the FLASER beams span")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 360.0));
  cmd->add_option("--carmen-max-time-step-s", c.carmen.max_time_step_s,
                  "CARMEN: a message stamped more than this after the previous one is a clock jump (an error)")
      ->capture_default_str()
      ->check(FinitePositive());
  cmd->add_option("--carmen-range-max-m", c.carmen.range_max_m, "CARMEN: longer ranges are no-returns")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  // ROS 1 and ROS 2 bags: "" = the one topic of the type, "none" = skip.
  io::RosbagTopics& topics = c.rosbag.topics;
  cmd->add_option("--cloud-topic", topics.cloud,
                  "rosbag, ros2: sensor_msgs/PointCloud2 topic (default: the only one; 'none')");
  cmd->add_option("--laser-topic", topics.laser,
                  "rosbag, ros2: sensor_msgs/LaserScan topic (default: the only one; 'none'); rosbag: also a "
                  "custom message holding one LaserScan field");
  cmd->add_option("--imu-topic", topics.imu, "rosbag, ros2: sensor_msgs/Imu topic (default: the only one; 'none')");
  cmd->add_option("--joint-topic", topics.joint,
                  "rosbag, ros2: sensor_msgs/JointState motor topic (default: the only one)");
  cmd->add_option("--joint-name", c.rosbag.joint_name,
                  "rosbag, ros2: joint whose position is the motor angle (default: first)");
  cmd->add_flag(
      "--no-clock-alignment", [&c](std::int64_t) { c.clocks.align = false; },
      "rosbag, ros2: topics stamped on different clocks are an error instead of being moved onto the "
      "bag's receive clock");
  cmd->add_option("--odometry-topic", topics.odometry,
                  "rosbag, ros2: nav_msgs/Odometry topic (default: the only one; 'none')");
  cmd->add_option("--groundtruth-topic", topics.groundtruth,
                  "rosbag, ros2: nav_msgs/Odometry or geometry_msgs/PoseStamped topic written as groundtruth.tum")
      ->capture_default_str();
  cmd->add_option("--angle-topic", topics.angle,
                  "rosbag, ros2: std_msgs Float32, Float64 or Int32 motor angle topic, stamped with the bag's receive "
                  "time (default: the only one; 'none'); rosbag: with --angle-field, any message type (it may be "
                  "the --laser-topic itself)");
  cmd->add_option("--angle-field", c.rosbag.angle_field,
                  "rosbag: the --angle-topic's number field holding the motor angle (e.g. stepAngle; nested with "
                  "'.'), read by the message definition in the bag");
  cmd->add_option("--angle-unit", options->angle_unit,
                  "rosbag, ros2: unit of the --angle-topic number (required with one)")
      ->check(CLI::IsMember({"deg", "rad"}));
  cmd->callback([options]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: stop reading, finish the dataset, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunConvert(*options));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
