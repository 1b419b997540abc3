#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace unimap::io {

// A recording in a format `unimap convert` reads, found where a dataset
// folder was expected.
struct RawInput {
  std::string format;       // convert's --format: "kitti", "carmen", "rosbag" or "ros2"
  std::string description;  // "a KITTI sequence", ...
};

// What `path` is when it is not a dataset: a ROS 2 bag (folder or .db3), a
// ROS 1 bag (.bag or its header), a CARMEN log (.clf / .log, also .bz2), or
// a KITTI sequence (a folder of numbered .bin / .pcd sweeps, or with a
// velodyne/ folder of them). std::nullopt otherwise. Never throws.
std::optional<RawInput> DetectRawInput(const std::filesystem::path& path);

// The error text for a raw recording given as a dataset: what it is and the
// convert command that makes a dataset of it.
std::string ConvertAdvice(const std::filesystem::path& path, const RawInput& raw);

}  // namespace unimap::io
