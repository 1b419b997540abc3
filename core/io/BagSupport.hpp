#pragma once
// Internal to unimap_io: what both bag readers (RosbagReader, Ros2BagReader)
// do alike: choosing topics by type, poses from position and quaternion,
// messages that name the bag, topic and time.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "io/BagTypes.hpp"

namespace unimap::io {

// The bag's topics, one per line ("\n  /scan (sensor_msgs/LaserScan, 298)"), for error messages.
std::string BagTopicList(const std::vector<RosbagTopicInfo>& topics);

// Resolves one stream's request (see RosbagTopics) to a topic, or "" when
// the stream is not read: "none", "" without allow_auto, or "" with no topic
// of an accepted type (a topic equal to `excluded`, the ground truth, does
// not count). Throws InputError "<bag>: <reason>; its topics: ..." for an
// absent topic, a topic of another type, or several candidates for "".
std::string ResolveBagTopic(const std::string& bag, const std::vector<RosbagTopicInfo>& topics,
                            const std::string& request, const std::vector<std::string>& types, const char* option,
                            bool allow_auto, const std::string& excluded);

// Pose from a position and a quaternion (w, x, y, z, any norm); false for a
// quaternion that cannot be normalized or a non-finite result. Never throws.
bool PoseToIsometry(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation, Eigen::Isometry3d* T);

// A LineScan from a LaserScan of either ROS version (same field names),
// stamped stamp_s; std::nullopt for a scan without beams.
template <class LaserScan>
std::optional<LineScan> ToLineScan(const LaserScan& scan, double stamp_s) {
  if (scan.ranges.empty()) return std::nullopt;
  LineScan line;
  line.start_time_s = stamp_s;
  line.angle_min_rad = scan.angle_min;
  line.angle_increment_rad = scan.angle_increment;
  line.time_increment_s = scan.time_increment;
  line.range_min_m = scan.range_min;
  line.range_max_m = scan.range_max;
  line.ranges_m = scan.ranges;
  if (scan.intensities.size() == scan.ranges.size()) line.intensities = scan.intensities;
  return line;
}

// The motor angle of a JointState: the position of joint `joint` (the first
// joint when empty). std::nullopt with *reason set when the message has no
// such joint or no finite position for it. Never throws.
std::optional<double> JointAngle(const std::vector<std::string>& names, const std::vector<double>& positions,
                                 const std::string& joint, std::string* reason);

// "<bag>: <topic> at t=<time_s, 17 digits>: <reason>", the form of a message error.
std::string BagMessageError(const std::string& bag, const std::string& topic, double time_s, const std::string& reason);

}  // namespace unimap::io
