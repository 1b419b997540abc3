#include "io/RawInput.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <system_error>

#include "io/Ros2BagMetadata.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// True when the file starts with a ROS 1 bag's version line.
bool HasRosbagHeader(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(13, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return in.gcount() == 13 && head == "#ROSBAG V2.0\n";
}

// True when the folder holds a sweep named by its frame number (000000.bin).
bool HasNumberedSweeps(const fs::path& folder) {
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    const std::string ext = p.extension().string();
    const std::string stem = p.stem().string();
    if ((ext == ".bin" || ext == ".pcd") && !stem.empty() &&
        std::all_of(stem.begin(), stem.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::optional<RawInput> DetectRawInput(const fs::path& path) {
  std::error_code ec;
  if (IsRos2Bag(path)) return RawInput{"ros2", "a ROS 2 bag"};
  if (fs::is_regular_file(path, ec)) {
    const std::string name = path.filename().string();
    if (path.extension() == ".bag" || HasRosbagHeader(path)) return RawInput{"rosbag", "a ROS 1 bag"};
    for (const char* end : {".clf", ".log", ".clf.bz2", ".log.bz2"}) {
      if (EndsWith(name, end)) return RawInput{"carmen", "a CARMEN log"};
    }
    return std::nullopt;
  }
  if (fs::is_directory(path, ec) && (HasNumberedSweeps(path) || HasNumberedSweeps(path / "velodyne"))) {
    return RawInput{"kitti", "a KITTI sequence"};
  }
  return std::nullopt;
}

std::string ConvertAdvice(const fs::path& path, const RawInput& raw) {
  std::string command = "unimap convert --format " + raw.format + " --input " + path.string() + " --out DATASET";
  if (raw.format == "ros2") command += " (add --angle-unit deg|rad for a scalar angle topic)";
  return path.string() + " is " + raw.description + ", not a dataset: convert it first with `" + command +
         "`, then give --data DATASET";
}

}  // namespace unimap::io
