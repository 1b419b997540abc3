#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "io/BagReader.hpp"
#include "io/BagTypes.hpp"

namespace unimap::io {

// Streams a ROS 2 bag with sqlite3 storage, uncompressed, CDR messages:
// a bag folder (metadata.yaml versions 4 to 9 and its .db3 files, split bags
// merged in timestamp order) or a single .db3 file. Messages come in
// timestamp order (the bag's receive time), one at a time, through libsqlite3
// and Fast CDR. Types (ROS 2 names): sensor_msgs/msg/PointCloud2, LaserScan,
// Imu, JointState, nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped and,
// as a motor angle (RosbagTopics::angle), std_msgs/msg/Float32, Float64 or
// Int32, stamped with the receive time (they have no header). Needs a build
// with UNIMAP_WITH_ROS2BAG; otherwise construction throws InputError saying so.
class Ros2BagReader : public BagReader {
 public:
  // Opens the bag and resolves the topics. Throws InputError naming the file:
  // an unreadable or unsupported metadata.yaml (mcap or other storage,
  // compression: saying what is read and to use `ros2 bag convert`), a missing
  // or damaged .db3, an unresolvable topic choice (listing the bag's topics),
  // a selected topic whose serialization is not cdr, a scalar angle topic
  // without RosbagReaderOptions::angle_unit, or both a joint and an angle topic.
  explicit Ros2BagReader(const std::filesystem::path& bag, RosbagReaderOptions options = {});
  ~Ros2BagReader();
  Ros2BagReader(const Ros2BagReader&) = delete;
  Ros2BagReader& operator=(const Ros2BagReader&) = delete;

  // Whether this build reads ROS 2 bags at all.
  static bool Supported();

  // The next message of a selected topic; std::nullopt at the end. A message
  // that cannot be converted (a LaserScan without beams, a JointState without
  // the joint, an odometry pose with a zero quaternion, non-finite IMU values)
  // is a counted skip; a truncated or malformed CDR message, a malformed cloud
  // or a damaged database throws InputError naming the .db3 file, topic and time.
  std::optional<RosbagMessage> Next() override;

 private:
  class Impl;
  const BagState& state() const override;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
