#pragma once
// Internal to unimap_io: buffered line-by-line reading of a text file.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace unimap::io {

// Reads a text file one line at a time through a fixed-size buffer, so memory
// does not grow with the file (only with the longest line, capped at
// kMaxLineBytes). Accepts "\n" and "\r\n" line ends and a last line without one.
class LineReader {
 public:
  // Longest accepted line; a longer one (e.g. a binary file) is an InputError.
  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

  // Opens the file; throws InputError naming it when it cannot be opened.
  explicit LineReader(const std::filesystem::path& file);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Points *line at the next line (without its line end), valid until the
  // next call; false at the end of the file. Throws InputError on a read
  // error or an over-long line.
  bool Next(std::string_view* line);
  // 1-based number of the line Next() returned last (0 before the first).
  std::int64_t line_number() const { return line_number_; }
  // The file as named in errors.
  const std::string& label() const { return label_; }

 private:
  // Reads more bytes after the unread ones; false at the end of the file.
  bool Fill();

  std::string label_;             // path as given, for messages
  std::FILE* file_ = nullptr;     // open stream, owned
  std::vector<char> buffer_;      // bytes read but not yet returned live in [begin_, end_)
  std::size_t begin_ = 0;         // first unread byte
  std::size_t end_ = 0;           // one past the last byte read
  std::size_t scanned_ = 0;       // bytes after begin_ already known to hold no '\n'
  bool at_eof_ = false;           // the file has no more bytes
  std::int64_t line_number_ = 0;  // lines returned so far
};

}  // namespace unimap::io
