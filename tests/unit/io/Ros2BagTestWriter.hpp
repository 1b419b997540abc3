#pragma once
// Shared by the Ros2BagReader tests: small ROS 2 bags written here (sqlite3
// storage as rosbag2 lays it out, messages serialized with Fast CDR in ROS 2
// IDL field order), and their metadata.yaml.
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <sqlite3.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "IoTestSupport.hpp"

namespace unimap::io::test {

using eprosima::fastcdr::Cdr;

// Serializes a message: encapsulation header, then fill(cdr) writes the fields.
template <class Fill>
std::vector<std::uint8_t> CdrBytes(Fill fill, Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS) {
  eprosima::fastcdr::FastBuffer buffer;
  Cdr cdr(buffer, endianness, Cdr::DDS_CDR);
  cdr.serialize_encapsulation();
  fill(cdr);
  const auto* begin = reinterpret_cast<const std::uint8_t*>(buffer.getBuffer());
  return std::vector<std::uint8_t>(begin, begin + cdr.getSerializedDataLength());
}

// std_msgs/msg/Header.
inline void WriteHeader(Cdr& cdr, std::int32_t sec, std::uint32_t nanosec) {
  cdr << sec << nanosec << std::string("frame");
}

// geometry_msgs/msg/Pose: position, then quaternion x y z w.
inline void WritePose(Cdr& cdr, const std::array<double, 3>& p, const std::array<double, 4>& q_xyzw) {
  cdr << p[0] << p[1] << p[2] << q_xyzw[0] << q_xyzw[1] << q_xyzw[2] << q_xyzw[3];
}

// A .db3 file with rosbag2's tables; topics and messages added one by one.
class Db3Writer {
 public:
  explicit Db3Writer(const std::filesystem::path& file) {
    if (sqlite3_open_v2(file.string().c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
        SQLITE_OK) {
      throw std::runtime_error("cannot create " + file.string());
    }
    Exec(
        "CREATE TABLE schema(schema_version INTEGER PRIMARY KEY,ros_distro TEXT NOT NULL);"
        "CREATE TABLE topics(id INTEGER PRIMARY KEY,name TEXT NOT NULL,type TEXT NOT NULL,"
        "serialization_format TEXT NOT NULL,offered_qos_profiles TEXT NOT NULL);"
        "CREATE TABLE messages(id INTEGER PRIMARY KEY,topic_id INTEGER NOT NULL,timestamp INTEGER NOT NULL,"
        "data BLOB NOT NULL);"
        "CREATE INDEX timestamp_idx ON messages (timestamp ASC);");
  }
  ~Db3Writer() { sqlite3_close(db_); }
  Db3Writer(const Db3Writer&) = delete;
  Db3Writer& operator=(const Db3Writer&) = delete;

  // Adds a topic; returns its id.
  std::int64_t AddTopic(const std::string& name, const std::string& type, const std::string& format = "cdr") {
    Exec("INSERT INTO topics(name, type, serialization_format, offered_qos_profiles) VALUES ('" + name + "', '" + type +
         "', '" + format + "', '')");
    return sqlite3_last_insert_rowid(db_);
  }
  // Adds a message received at timestamp_ns.
  void Write(std::int64_t topic_id, std::int64_t timestamp_ns, const std::vector<std::uint8_t>& data) {
    sqlite3_stmt* statement = nullptr;
    sqlite3_prepare_v2(db_, "INSERT INTO messages(topic_id, timestamp, data) VALUES (?, ?, ?)", -1, &statement,
                       nullptr);
    sqlite3_bind_int64(statement, 1, topic_id);
    sqlite3_bind_int64(statement, 2, timestamp_ns);
    sqlite3_bind_blob(statement, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    const int code = sqlite3_step(statement);
    sqlite3_finalize(statement);
    if (code != SQLITE_DONE) throw std::runtime_error("cannot insert a message");
  }

 private:
  void Exec(const std::string& sql) {
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) {
      throw std::runtime_error(std::string("sqlite: ") + sqlite3_errmsg(db_));
    }
  }
  sqlite3* db_ = nullptr;
};

// A topic line of metadata.yaml.
struct MetadataTopic {
  std::string name;
  std::string type;
  std::size_t count = 0;
};

// Writes <folder>/metadata.yaml (version 5, as rosbag2 writes it) listing `files`.
inline void WriteRos2Metadata(const std::filesystem::path& folder, const std::vector<std::string>& files,
                              const std::vector<MetadataTopic>& topics, const std::string& storage = "sqlite3",
                              const std::string& compression_format = "", const std::string& compression_mode = "") {
  std::string text =
      "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: " + storage +
      "\n  duration:\n    nanoseconds: 1\n  starting_time:\n    nanoseconds_since_epoch: 0\n  message_count: 0\n"
      "  topics_with_message_count:\n";
  for (const MetadataTopic& t : topics) {
    text += "    - topic_metadata:\n        name: " + t.name + "\n        type: " + t.type +
            "\n        serialization_format: cdr\n        offered_qos_profiles: \"\"\n      message_count: " +
            std::to_string(t.count) + "\n";
  }
  text += "  compression_format: \"" + compression_format + "\"\n  compression_mode: \"" + compression_mode +
          "\"\n  relative_file_paths:\n";
  for (const std::string& f : files) text += "    - " + f + "\n";
  WriteText(folder / "metadata.yaml", text);
}

}  // namespace unimap::io::test
