#include "io/Ros2BagDatabase.hpp"

#if UNIMAP_WITH_ROS2BAG
#include <sqlite3.h>

#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// A statement finalized on scope exit.
class Statement {
 public:
  explicit Statement(sqlite3_stmt* statement) : statement_(statement) {}
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() const { return statement_; }

 private:
  sqlite3_stmt* statement_;
};

// A text column ("" for NULL).
std::string Text(sqlite3_stmt* statement, int column) {
  const unsigned char* text = sqlite3_column_text(statement, column);
  return text == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(text));
}

}  // namespace

Ros2BagDatabase::Ros2BagDatabase(const std::filesystem::path& file) : file_(file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file.string() + ": no such bag file");
  // A constructor that throws runs no destructor: the handle (which
  // sqlite3_open_v2 allocates even when it fails) is closed here then.
  try {
    if (sqlite3_open_v2(file.string().c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
      Fail("cannot open as an SQLite database");
    }
    const Statement topics(Prepare("SELECT id, name, type, serialization_format FROM topics ORDER BY id"));
    int code = SQLITE_ROW;
    while ((code = sqlite3_step(topics.get())) == SQLITE_ROW) {
      topics_.push_back(
          {sqlite3_column_int64(topics.get(), 0), Text(topics.get(), 1), Text(topics.get(), 2), Text(topics.get(), 3)});
    }
    if (code != SQLITE_DONE) Fail("cannot read the topics table");
    const Statement messages(Prepare("SELECT id, topic_id, timestamp, data FROM messages LIMIT 0"));  // exists
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

Ros2BagDatabase::~Ros2BagDatabase() {
  sqlite3_finalize(query_);
  sqlite3_close(db_);
}

void Ros2BagDatabase::Fail(const std::string& what) const {
  const char* reason = db_ == nullptr ? "out of memory" : sqlite3_errmsg(db_);
  throw InputError(file_.string() + ": " + what + ": " + reason + " (not a rosbag2 sqlite3 file, or damaged)");
}

sqlite3_stmt* Ros2BagDatabase::Prepare(const std::string& sql) const {
  sqlite3_stmt* statement = nullptr;
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &statement, nullptr) != SQLITE_OK) {
    sqlite3_finalize(statement);
    Fail("cannot query \"" + sql + "\"");
  }
  return statement;
}

std::vector<std::pair<std::int64_t, std::size_t>> Ros2BagDatabase::CountMessages() {
  const Statement count(Prepare("SELECT topic_id, COUNT(*) FROM messages GROUP BY topic_id"));
  std::vector<std::pair<std::int64_t, std::size_t>> counts;
  int code = SQLITE_ROW;
  while ((code = sqlite3_step(count.get())) == SQLITE_ROW) {
    counts.emplace_back(sqlite3_column_int64(count.get(), 0),
                        static_cast<std::size_t>(sqlite3_column_int64(count.get(), 1)));
  }
  if (code != SQLITE_DONE) Fail("cannot count the messages");
  return counts;
}

void Ros2BagDatabase::Query(const std::vector<std::int64_t>& ids) {
  sqlite3_finalize(query_);
  query_ = nullptr;
  row_ = Row{};
  if (ids.empty()) return;
  std::ostringstream sql;
  sql << "SELECT timestamp, topic_id, data FROM messages WHERE topic_id IN (";
  for (std::size_t k = 0; k < ids.size(); ++k) sql << (k == 0 ? "" : ", ") << ids[k];
  sql << ") ORDER BY timestamp, id";
  query_ = Prepare(sql.str());
}

bool Ros2BagDatabase::Step() {
  if (query_ == nullptr) return false;
  const int code = sqlite3_step(query_);
  if (code == SQLITE_DONE) {
    sqlite3_finalize(query_);
    query_ = nullptr;
    return false;
  }
  if (code != SQLITE_ROW) {
    std::ostringstream where;
    where.precision(17);
    where << "corrupt database after t=" << static_cast<double>(row_.timestamp_ns) / 1e9;
    Fail(where.str());
  }
  row_.timestamp_ns = sqlite3_column_int64(query_, 0);
  row_.topic_id = sqlite3_column_int64(query_, 1);
  row_.data = static_cast<const std::uint8_t*>(sqlite3_column_blob(query_, 2));
  row_.size = static_cast<std::size_t>(sqlite3_column_bytes(query_, 2));
  return true;
}

}  // namespace unimap::io
#endif  // UNIMAP_WITH_ROS2BAG
