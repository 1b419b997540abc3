#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "io/BagReader.hpp"
#include "io/BagTypes.hpp"

namespace unimap::io {

// Streams a ROS 1 bag (format 2.0; uncompressed, bz2 or lz4 chunks) through
// librosbag_storage, in bag order, one message at a time. Needs a build with
// UNIMAP_WITH_ROSBAG; otherwise construction throws InputError saying so.
class RosbagReader : public BagReader {
 public:
  // Opens the bag and resolves the topics; throws InputError for an
  // unreadable bag or an unresolvable topic choice (listing the bag's topics).
  explicit RosbagReader(const std::filesystem::path& bag, RosbagReaderOptions options = {});
  ~RosbagReader();
  RosbagReader(const RosbagReader&) = delete;
  RosbagReader& operator=(const RosbagReader&) = delete;

  // Whether this build reads bags at all.
  static bool Supported();

  // The next message of a selected topic; std::nullopt at the end. A message
  // that cannot be converted (a JointState without positions, an odometry
  // pose with a zero quaternion) is a counted skip; a damaged chunk or a
  // malformed cloud throws InputError naming the bag, topic and time.
  std::optional<RosbagMessage> Next() override;

 private:
  class Impl;
  const BagState& state() const override;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
