#pragma once
// Internal to unimap_io: metadata.yaml of a ROS 2 bag folder (rosbag2), the
// parts Ros2BagReader needs.
#include <filesystem>
#include <string>
#include <vector>

#include "io/BagTypes.hpp"

namespace unimap::io {

// rosbag2_bagfile_information of metadata.yaml (versions 4 to 9).
struct Ros2BagMetadata {
  std::filesystem::path file;                // the metadata.yaml read, for messages
  int version = 0;                           // metadata version
  std::string storage_identifier;            // "sqlite3" (the only storage read)
  std::vector<std::filesystem::path> files;  // relative_file_paths, resolved against the folder, in listed order
  std::vector<RosbagTopicInfo> topics;       // topics_with_message_count (name, type, message count)
};

// Whether `path` is a ROS 2 bag: a folder (or its metadata.yaml) whose
// metadata.yaml holds rosbag2_bagfile_information, or a .db3 file that
// starts as an SQLite database. Never throws (unreadable = false).
bool IsRos2Bag(const std::filesystem::path& path);

// Reads <folder>/metadata.yaml. Throws InputError "<file>: <reason>" when it
// is missing or not YAML, lacks rosbag2_bagfile_information, version,
// storage_identifier or relative_file_paths, has a version outside 4..9, a
// storage other than sqlite3 or a compression (these two say what is read
// and how to convert the bag with `ros2 bag convert`), or lists a bag file
// that does not exist ("<bag file>: missing ...").
Ros2BagMetadata ReadRos2BagMetadata(const std::filesystem::path& folder);

}  // namespace unimap::io
