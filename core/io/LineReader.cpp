#include "io/LineReader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kChunkBytes = std::size_t{64} << 10;  // bytes per read

}  // namespace

LineReader::LineReader(const std::filesystem::path& file) : label_(file.string()), buffer_(kChunkBytes) {
  file_ = std::fopen(label_.c_str(), "rb");
  if (file_ == nullptr) {
    throw InputError(label_ + ": cannot open for reading: " + std::strerror(errno));
  }
}

LineReader::~LineReader() { std::fclose(file_); }

bool LineReader::Fill() {
  if (at_eof_) return false;
  if (begin_ > 0) {  // move the unread bytes to the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) {
    if (buffer_.size() >= kMaxLineBytes) {
      throw InputError(label_ + ":" + std::to_string(line_number_ + 1) + ": line longer than " +
                       std::to_string(kMaxLineBytes) + " bytes (not a text file?)");
    }
    buffer_.resize(buffer_.size() * 2);
  }
  const std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
  if (got == 0) {
    if (std::ferror(file_) != 0) {
      throw InputError(label_ + ":" + std::to_string(line_number_ + 1) + ": read error");
    }
    at_eof_ = true;
    return false;
  }
  end_ += got;
  return true;
}

bool LineReader::Next(std::string_view* line) {
  for (;;) {
    const char* first = buffer_.data() + begin_;
    const char* last = buffer_.data() + end_;
    const char* newline = std::find(first + scanned_, last, '\n');
    std::size_t length = 0;
    if (newline != last) {
      length = static_cast<std::size_t>(newline - first);
      begin_ += length + 1;
    } else {
      const std::size_t unread = end_ - begin_;  // known to hold no '\n'
      if (Fill()) {
        scanned_ = unread;
        continue;
      }
      if (begin_ == end_) return false;
      first = buffer_.data() + begin_;  // a last line without a line end
      length = end_ - begin_;
      begin_ = end_;
    }
    scanned_ = 0;
    if (length > 0 && first[length - 1] == '\r') --length;
    ++line_number_;
    *line = std::string_view(first, length);
    return true;
  }
}

}  // namespace unimap::io
