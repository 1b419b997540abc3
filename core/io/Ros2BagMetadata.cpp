#include "io/Ros2BagMetadata.hpp"

#include <fstream>

#include <yaml-cpp/yaml.h>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRoot = "rosbag2_bagfile_information";
// How to turn any rosbag2 bag into one this reader reads.
constexpr const char* kConvertHint =
    "unimap reads rosbag2 bags with sqlite3 storage (.db3), uncompressed; convert this one with `ros2 bag convert "
    "-i <bag> -o out.yaml`, out.yaml holding output_bags: [{uri: <new bag>, storage_id: sqlite3}] (no "
    "compression_mode)";

// The metadata.yaml of a bag given as its folder or as the file itself.
fs::path MetadataFile(const fs::path& path) {
  return path.filename() == "metadata.yaml" ? path : path / "metadata.yaml";
}

// A string key of `node` ("" when absent); throws for another type.
std::string OptionalString(const YAML::Node& node, const char* key, const std::string& file) {
  const YAML::Node value = node[key];
  if (!value) return "";
  if (!value.IsScalar()) throw InputError(file + ": " + kRoot + "." + key + " is not a string");
  return value.as<std::string>();
}

// A required key of `node`.
YAML::Node Required(const YAML::Node& node, const char* key, const std::string& file) {
  const YAML::Node value = node[key];
  if (!value) throw InputError(file + ": no " + key + " under " + kRoot + " (not a rosbag2 metadata.yaml?)");
  return value;
}

}  // namespace

bool IsRos2Bag(const fs::path& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec) && path.extension() == ".db3") {
    std::ifstream in(path, std::ios::binary);
    char magic[16] = {};
    in.read(magic, sizeof(magic));
    return in.gcount() == sizeof(magic) && std::string(magic, 15) == "SQLite format 3";
  }
  const fs::path metadata = MetadataFile(path);
  if (!fs::is_regular_file(metadata, ec)) return false;
  try {
    return YAML::LoadFile(metadata.string())[kRoot].IsMap();
  } catch (const YAML::Exception&) {
    return false;
  }
}

Ros2BagMetadata ReadRos2BagMetadata(const fs::path& folder) {
  Ros2BagMetadata metadata;
  metadata.file = MetadataFile(folder);
  const std::string file = metadata.file.string();
  try {
    if (!fs::is_regular_file(metadata.file)) throw InputError(file + ": no such file (not a rosbag2 bag folder)");
    const YAML::Node root = YAML::LoadFile(file)[kRoot];
    if (!root.IsMap()) throw InputError(file + ": no " + kRoot + " map (not a rosbag2 metadata.yaml)");
    metadata.version = Required(root, "version", file).as<int>();
    if (metadata.version < 4 || metadata.version > 9) {
      throw InputError(file + ": rosbag2 metadata version " + std::to_string(metadata.version) +
                       "; versions 4 to 9 are read");
    }
    metadata.storage_identifier = Required(root, "storage_identifier", file).as<std::string>();
    if (metadata.storage_identifier != "sqlite3") {
      throw InputError(file + ": storage_identifier " + metadata.storage_identifier + ": " + kConvertHint);
    }
    for (const char* key : {"compression_format", "compression_mode"}) {
      const std::string value = OptionalString(root, key, file);
      if (!value.empty()) throw InputError(file + ": " + key + " " + value + " (a compressed bag): " + kConvertHint);
    }
    const YAML::Node paths = Required(root, "relative_file_paths", file);
    if (!paths.IsSequence() || paths.size() == 0) throw InputError(file + ": relative_file_paths lists no file");
    const fs::path dir = metadata.file.parent_path();
    for (const YAML::Node& relative : paths) {
      fs::path path = dir / relative.as<std::string>();
      // Bags from before version 4 named files from the parent folder ("<bag>/<bag>_0.db3").
      if (!fs::exists(path) && fs::exists(dir.parent_path() / relative.as<std::string>())) {
        path = dir.parent_path() / relative.as<std::string>();
      }
      if (!fs::is_regular_file(path)) {
        throw InputError(path.string() + ": missing (" + file + " lists it in relative_file_paths)");
      }
      metadata.files.push_back(path);
    }
    for (const YAML::Node& entry : root["topics_with_message_count"]) {
      const YAML::Node topic = entry["topic_metadata"];
      if (!topic.IsMap()) continue;
      RosbagTopicInfo info;
      info.topic = OptionalString(topic, "name", file);
      info.datatype = OptionalString(topic, "type", file);
      info.messages = entry["message_count"] ? entry["message_count"].as<std::size_t>() : 0;
      metadata.topics.push_back(info);
    }
  } catch (const YAML::Exception& e) {
    throw InputError(file + ": " + e.what());
  }
  return metadata;
}

}  // namespace unimap::io
