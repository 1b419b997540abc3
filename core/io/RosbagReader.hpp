#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "io/PointCloud2Decoder.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/LineScan.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/RawScan.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Topic per stream: "" = the one topic of that message type in the bag
// (none if the bag has none; an error if it has several), "none" = not read,
// anything else = that topic (an error if absent or of another type).
struct RosbagTopics {
  std::string cloud;                 // sensor_msgs/PointCloud2 -> RawScan
  std::string laser;                 // sensor_msgs/LaserScan -> LineScan
  std::string imu;                   // sensor_msgs/Imu -> ImuSample
  std::string joint;                 // sensor_msgs/JointState -> EncoderSample (motor angle)
  std::string odometry;              // nav_msgs/Odometry -> OdometrySample
  std::string groundtruth = "none";  // nav_msgs/Odometry or geometry_msgs/PoseStamped -> StampedPose; never auto
};

struct RosbagReaderOptions {
  RosbagTopics topics;     // which topics to read
  std::string joint_name;  // JointState: joint whose position is the motor angle; empty = the first
};

// A bag topic, as listed in the bag's index.
struct RosbagTopicInfo {
  std::string topic;
  std::string datatype;      // e.g. "sensor_msgs/PointCloud2"
  std::size_t messages = 0;  // messages on the topic
};

// One message turned into unimap's types; times are header stamps (the
// bag's receive time when a header stamp is zero).
struct RosbagMessage {
  std::string topic;
  double stamp_s = 0.0;  // header stamp (or receive time, see above)
  std::variant<RawScan, LineScan, ImuSample, EncoderSample, OdometrySample, StampedPose> data;
  std::size_t dropped_points = 0;                                    // clouds: points with non-finite fields left out
  PointTimeConvention time_convention = PointTimeConvention::kNone;  // clouds: how point times were read
};

// What the reader has delivered and skipped so far.
struct RosbagReaderStats {
  std::map<std::string, std::size_t> delivered;  // topic -> messages delivered
  std::map<std::string, std::size_t> skipped;    // reason -> messages skipped
  std::size_t dropped_points = 0;                // cloud points left out (non-finite)
};

// Streams a ROS 1 bag (format 2.0; uncompressed, bz2 or lz4 chunks) through
// librosbag_storage, in bag order, one message at a time. Needs a build with
// UNIMAP_WITH_ROSBAG; otherwise construction throws InputError saying so.
class RosbagReader {
 public:
  // Opens the bag and resolves the topics; throws InputError for an
  // unreadable bag or an unresolvable topic choice (listing the bag's topics).
  explicit RosbagReader(const std::filesystem::path& bag, RosbagReaderOptions options = {});
  ~RosbagReader();
  RosbagReader(const RosbagReader&) = delete;
  RosbagReader& operator=(const RosbagReader&) = delete;

  // Whether this build reads bags at all.
  static bool Supported();

  // Every topic in the bag.
  const std::vector<RosbagTopicInfo>& topics() const;
  // The topics chosen (empty string = that stream is not read).
  const RosbagTopics& selected() const;

  // The next message of a selected topic; std::nullopt at the end. A message
  // that cannot be converted (a JointState without positions, an odometry
  // pose with a zero quaternion) is a counted skip; a damaged chunk or a
  // malformed cloud throws InputError naming the bag, topic and time.
  std::optional<RosbagMessage> Next();
  const RosbagReaderStats& stats() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
