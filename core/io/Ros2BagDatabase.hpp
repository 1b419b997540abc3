#pragma once
// Internal to unimap_io: one file of a ROS 2 bag with sqlite3 storage (.db3),
// read through libsqlite3. Needs a build with UNIMAP_WITH_ROS2BAG.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace unimap::io {

// Opens a .db3 read-only and streams its messages table in timestamp order,
// one row at a time (the table is never loaded whole).
class Ros2BagDatabase {
 public:
  // A row of the topics table.
  struct Topic {
    std::int64_t id = 0;               // topics.id (what messages.topic_id refers to)
    std::string name;                  // "/scan"
    std::string type;                  // "sensor_msgs/msg/LaserScan"
    std::string serialization_format;  // "cdr"
  };
  // The current row of the message query; data is valid until the next Step().
  struct Row {
    std::int64_t timestamp_ns = 0;       // the bag's receive time
    std::int64_t topic_id = 0;           // topics.id
    const std::uint8_t* data = nullptr;  // serialized message
    std::size_t size = 0;                // bytes at data
  };

  // Opens the file and reads its topics table; throws InputError "<file>: <reason>"
  // when it is missing, not an SQLite database, or has no topics/messages table.
  explicit Ros2BagDatabase(const std::filesystem::path& file);
  ~Ros2BagDatabase();
  Ros2BagDatabase(const Ros2BagDatabase&) = delete;
  Ros2BagDatabase& operator=(const Ros2BagDatabase&) = delete;

  const std::filesystem::path& file() const { return file_; }
  const std::vector<Topic>& topics() const { return topics_; }

  // Messages per topic id (a scan of the messages table); throws InputError for a corrupt database.
  std::vector<std::pair<std::int64_t, std::size_t>> CountMessages();

  // Starts the messages of the topics `ids` in timestamp order (then row id).
  // Throws InputError for a corrupt database.
  void Query(const std::vector<std::int64_t>& ids);
  // Moves to the next row of the query: false at the end (or with no query).
  // Throws InputError "<file>: corrupt database after t=<s>: <sqlite message>".
  bool Step();
  const Row& row() const { return row_; }

 private:
  // Throws InputError "<file>: <what>: <sqlite's message>".
  [[noreturn]] void Fail(const std::string& what) const;
  // Prepares `sql`; throws through Fail.
  sqlite3_stmt* Prepare(const std::string& sql) const;

  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* query_ = nullptr;  // the message query, or null
  std::vector<Topic> topics_;
  Row row_;
};

}  // namespace unimap::io
