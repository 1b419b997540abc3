#pragma once
// Internal to unimap_io: the ROS 2 messages Ros2BagReader reads, decoded from
// their CDR serialization (XCDR1 plain CDR, either byte order, as rosbag2
// stores them) with Fast CDR, fields in ROS 2 IDL order. Needs a build with
// UNIMAP_WITH_ROS2BAG.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "io/PointCloud2Decoder.hpp"

namespace unimap::io {

// builtin_interfaces/msg/Time, the stamp of std_msgs/msg/Header.
struct CdrTime {
  std::int32_t sec = 0;       // seconds
  std::uint32_t nanosec = 0;  // nanoseconds within the second
  bool IsZero() const { return sec == 0 && nanosec == 0; }
  double Seconds() const { return static_cast<double>(sec) + static_cast<double>(nanosec) / 1e9; }
};

// sensor_msgs/msg/LaserScan.
struct CdrLaserScan {
  CdrTime stamp;                   // header.stamp
  float angle_min = 0.0f;          // rad, first beam
  float angle_max = 0.0f;          // rad, last beam
  float angle_increment = 0.0f;    // rad between beams
  float time_increment = 0.0f;     // s between beams
  float scan_time = 0.0f;          // s between scans
  float range_min = 0.0f;          // m
  float range_max = 0.0f;          // m
  std::vector<float> ranges;       // m per beam
  std::vector<float> intensities;  // per beam, or empty
};

// sensor_msgs/msg/Imu (orientation and covariances are read past, not kept).
struct CdrImu {
  CdrTime stamp;                                                  // header.stamp
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();     // rad/s
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();  // m/s^2
};

// sensor_msgs/msg/JointState.
struct CdrJointState {
  CdrTime stamp;                  // header.stamp
  std::vector<std::string> name;  // joint names
  std::vector<double> position;   // rad (or m), per joint
};

// geometry_msgs/msg/PoseStamped, and the pose part of nav_msgs/msg/Odometry.
struct CdrPoseStamped {
  CdrTime stamp;                                                    // header.stamp
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               // pose.position
  Eigen::Quaterniond orientation = Eigen::Quaterniond(0, 0, 0, 0);  // pose.orientation, as stored (any norm)
};

// sensor_msgs/msg/PointCloud2.
struct CdrPointCloud2 {
  CdrTime stamp;                   // header.stamp
  std::uint32_t height = 0;        // rows
  std::uint32_t width = 0;         // points per row
  std::vector<CloudField> fields;  // sensor_msgs/msg/PointField
  bool is_bigendian = false;       // byte order of data
  std::uint32_t point_step = 0;    // bytes per point
  std::uint32_t row_step = 0;      // bytes per row
  std::vector<std::uint8_t> data;  // the points
};

// std_msgs/msg scalars read as an angle.
enum class CdrScalar { kFloat32, kFloat64, kInt32 };

// Each decodes one serialized message (4-byte encapsulation header, then
// the fields). Throws InputError "truncated CDR message ..." when the data
// ends before the last field, or "malformed CDR message ..." for an unknown
// encapsulation or an invalid value (a bool other than 0 or 1). Bytes after
// the last field are ignored.
CdrLaserScan DecodeLaserScan(const std::uint8_t* data, std::size_t size);
CdrImu DecodeImu(const std::uint8_t* data, std::size_t size);
CdrJointState DecodeJointState(const std::uint8_t* data, std::size_t size);
CdrPoseStamped DecodePoseStamped(const std::uint8_t* data, std::size_t size);
CdrPoseStamped DecodeOdometry(const std::uint8_t* data, std::size_t size);  // header + pose.pose (twist read past)
CdrPointCloud2 DecodePointCloud2(const std::uint8_t* data, std::size_t size);
double DecodeScalar(CdrScalar type, const std::uint8_t* data, std::size_t size);

}  // namespace unimap::io
