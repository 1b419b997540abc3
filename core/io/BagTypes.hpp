#pragma once
// The types both bag readers share (RosbagReader: ROS 1, Ros2BagReader:
// ROS 2): topic choice, options, topic list, converted messages and stats.
#include <cstddef>
#include <map>
#include <string>
#include <variant>

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
// Type names are ROS 1's ("sensor_msgs/PointCloud2"); a ROS 2 bag's are
// the same with "/msg/" ("sensor_msgs/msg/PointCloud2").
struct RosbagTopics {
  std::string cloud;                 // sensor_msgs/PointCloud2 -> RawScan
  std::string laser;                 // sensor_msgs/LaserScan -> LineScan (ROS 1 also: a message holding one)
  std::string imu;                   // sensor_msgs/Imu -> ImuSample
  std::string joint;                 // sensor_msgs/JointState -> EncoderSample (motor angle)
  std::string odometry;              // nav_msgs/Odometry -> OdometrySample
  std::string groundtruth = "none";  // nav_msgs/Odometry or geometry_msgs/PoseStamped -> StampedPose; never auto
  std::string angle;                 // std_msgs Float32, Float64 or Int32 -> EncoderSample (motor angle in
                                     // RosbagReaderOptions::angle_unit; stamped with the bag's receive time:
                                     // these messages have no header). ROS 1 also: any message with a
                                     // number field named by RosbagReaderOptions::angle_field, stamped by
                                     // its header, by the scan it comes with, else by the receive time
};

// Unit of a scalar angle topic's number (it carries none).
enum class AngleUnit {
  kUnset,    // not given: reading a scalar angle topic is an error
  kDegrees,  // deg
  kRadians,  // rad
};

struct RosbagReaderOptions {
  RosbagTopics topics;                       // which topics to read
  std::string joint_name;                    // JointState: joint whose position is the motor angle; empty = the first
  AngleUnit angle_unit = AngleUnit::kUnset;  // unit of the angle topic's number; required when one is read
  std::string angle_field;                   // ROS 1: the angle topic's number field ('.' for nested fields),
                                             // read by the message definition the bag carries; empty = "data"
                                             // of a std_msgs scalar
};

// A bag topic, as listed in the bag's index.
struct RosbagTopicInfo {
  std::string topic;
  std::string datatype;      // e.g. "sensor_msgs/PointCloud2" (ROS 2: "sensor_msgs/msg/PointCloud2")
  std::size_t messages = 0;  // messages on the topic
  std::string definition;    // ROS 1: the message definition of the topic's connection (empty for ROS 2)
};

// One message turned into unimap's types; times are header stamps (the
// bag's receive time when a header stamp is zero, or the message has none).
struct RosbagMessage {
  std::string topic;
  double stamp_s = 0.0;    // header stamp (or receive time, see above)
  double receive_s = 0.0;  // the bag's receive (record) time
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

}  // namespace unimap::io
