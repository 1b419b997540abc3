#pragma once
// Internal to unimap_io: line-by-line reading of a plain or bzip2-compressed
// text file (CARMEN logs, KITTI text files), streamed through fixed buffers.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace unimap::io {

// Reads lines from a text file that may be bzip2-compressed (detected from
// the "BZh" magic, not the file name; concatenated bzip2 streams as written
// by pbzip2 are read one after the other). Memory stays bounded by the
// buffers plus the longest line (at most kMaxLineBytes).
class TextLineSource {
 public:
  // Longest accepted line; a longer one (a binary file) is an InputError.
  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 22;

  // Opens the file; throws InputError naming it when it cannot be opened.
  explicit TextLineSource(const std::filesystem::path& file);
  ~TextLineSource();
  TextLineSource(const TextLineSource&) = delete;
  TextLineSource& operator=(const TextLineSource&) = delete;

  // Copies the next line (without "\n" or "\r\n") into *line; false at the
  // end of the file. Throws InputError "<file>:<line>: <reason>" on a read
  // error, corrupt compressed data or an over-long line. A compressed stream
  // that ends early (truncated file) ends the text there: the partial last
  // line is returned with ended_with_newline() false.
  bool Next(std::string* line);
  // 1-based number of the line Next() returned last (0 before the first).
  std::int64_t line_number() const { return line_number_; }
  // False when the line Next() returned last was cut by the end of the file.
  bool ended_with_newline() const { return ended_with_newline_; }
  // True when the compressed data ended before its end-of-stream marker.
  bool truncated() const { return truncated_; }
  // The file as named in errors.
  const std::string& label() const { return label_; }

 private:
  // Reads more decompressed bytes into text_; false at the end of the data.
  bool Fill();
  // Decompresses into out[0, capacity); returns bytes produced (0 at the end).
  std::size_t ReadCompressed(char* out, std::size_t capacity);
  // Starts a bzip2 stream on the unread bytes of compressed_.
  void StartStream();
  // Ends the current bzip2 stream.
  void EndStream();
  // Throws InputError "<file>:<line>: <reason>".
  [[noreturn]] void Fail(const std::string& reason) const;

  std::string label_;              // path as given, for messages
  std::FILE* file_ = nullptr;      // open stream, owned
  bool compressed_input_ = false;  // the file starts with the bzip2 magic
  void* bz_stream_ = nullptr;      // bz_stream* while a stream is open (owned)
  std::vector<char> compressed_;   // compressed bytes read from the file, [compressed_begin_, compressed_end_) unread
  std::size_t compressed_begin_ = 0;  // first unread compressed byte
  std::size_t compressed_end_ = 0;    // one past the last compressed byte read
  bool file_eof_ = false;             // the file has no more bytes
  bool data_eof_ = false;             // no more text will come
  std::vector<char> text_;            // decompressed text, [text_begin_, text_end_) unread
  std::size_t text_begin_ = 0;        // first unread text byte
  std::size_t text_end_ = 0;          // one past the last text byte
  std::int64_t line_number_ = 0;      // lines returned so far
  bool ended_with_newline_ = true;    // see ended_with_newline()
  bool truncated_ = false;            // see truncated()
};

}  // namespace unimap::io
