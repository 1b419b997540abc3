#include "io/TextLineSource.hpp"

#include <bzlib.h>

#include <algorithm>
#include <cstring>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kChunkBytes = std::size_t{1} << 16;  // read / decompress granularity

bz_stream* AsStream(void* p) { return static_cast<bz_stream*>(p); }

}  // namespace

TextLineSource::TextLineSource(const std::filesystem::path& file)
    : label_(file.string()), compressed_(kChunkBytes), text_(kChunkBytes) {
  file_ = std::fopen(label_.c_str(), "rb");
  if (file_ == nullptr) throw InputError(label_ + ": cannot open file: " + std::strerror(errno));
  // The bzip2 magic is "BZh" followed by the block size digit '1'..'9'.
  compressed_end_ = std::fread(compressed_.data(), 1, compressed_.size(), file_);
  if (compressed_end_ < compressed_.size()) {
    if (std::ferror(file_)) {
      std::fclose(file_);
      throw InputError(label_ + ": read error");
    }
    file_eof_ = true;
  }
  compressed_input_ = compressed_end_ >= 4 && std::memcmp(compressed_.data(), "BZh", 3) == 0 && compressed_[3] >= '1' &&
                      compressed_[3] <= '9';
  if (!compressed_input_) {
    // Plain text: the bytes already read are the first text bytes.
    text_.swap(compressed_);
    text_end_ = compressed_end_;
    compressed_end_ = 0;
    compressed_.clear();
    compressed_.shrink_to_fit();
  }
}

TextLineSource::~TextLineSource() {
  EndStream();
  if (file_ != nullptr) std::fclose(file_);
}

void TextLineSource::Fail(const std::string& reason) const {
  throw InputError(label_ + ":" + std::to_string(line_number_ + 1) + ": " + reason);
}

void TextLineSource::StartStream() {
  auto* stream = new bz_stream();
  std::memset(stream, 0, sizeof(bz_stream));
  if (BZ2_bzDecompressInit(stream, 0, 0) != BZ_OK) {
    delete stream;
    Fail("cannot initialise the bzip2 decompressor");
  }
  bz_stream_ = stream;
}

void TextLineSource::EndStream() {
  if (bz_stream_ == nullptr) return;
  BZ2_bzDecompressEnd(AsStream(bz_stream_));
  delete AsStream(bz_stream_);
  bz_stream_ = nullptr;
}

std::size_t TextLineSource::ReadCompressed(char* out, std::size_t capacity) {
  for (;;) {
    if (compressed_begin_ == compressed_end_ && !file_eof_) {
      compressed_begin_ = 0;
      compressed_end_ = std::fread(compressed_.data(), 1, compressed_.size(), file_);
      if (compressed_end_ < compressed_.size()) {
        if (std::ferror(file_)) Fail("read error");
        file_eof_ = true;
      }
    }
    const std::size_t available = compressed_end_ - compressed_begin_;
    if (bz_stream_ == nullptr) {
      if (available == 0) return 0;  // every stream ended cleanly
      StartStream();
    }
    if (available == 0) {  // the file ended inside a stream
      truncated_ = true;
      EndStream();
      return 0;
    }
    bz_stream* stream = AsStream(bz_stream_);
    stream->next_in = compressed_.data() + compressed_begin_;
    stream->avail_in = static_cast<unsigned int>(available);
    stream->next_out = out;
    stream->avail_out = static_cast<unsigned int>(capacity);
    const int code = BZ2_bzDecompress(stream);
    compressed_begin_ += available - stream->avail_in;
    const std::size_t produced = capacity - stream->avail_out;
    if (code == BZ_STREAM_END) {
      EndStream();
    } else if (code != BZ_OK) {
      Fail("corrupt bzip2 data (libbz2 code " + std::to_string(code) + ")");
    }
    if (produced > 0) return produced;
  }
}

bool TextLineSource::Fill() {
  if (data_eof_) return false;
  // Keep the unread bytes, moved to the front; grow only for a long line.
  const std::size_t unread = text_end_ - text_begin_;
  std::memmove(text_.data(), text_.data() + text_begin_, unread);
  text_begin_ = 0;
  text_end_ = unread;
  if (text_.size() - text_end_ < kChunkBytes / 2) text_.resize(text_.size() + kChunkBytes);
  const std::size_t capacity = text_.size() - text_end_;
  std::size_t produced = 0;
  if (compressed_input_) {
    produced = ReadCompressed(text_.data() + text_end_, capacity);
  } else if (!file_eof_) {
    produced = std::fread(text_.data() + text_end_, 1, capacity, file_);
    if (produced < capacity) {
      if (std::ferror(file_)) Fail("read error");
      file_eof_ = true;
    }
  }
  if (produced == 0) {
    data_eof_ = true;
    return false;
  }
  text_end_ += produced;
  return true;
}

bool TextLineSource::Next(std::string* line) {
  std::size_t scanned = 0;  // bytes after text_begin_ known to hold no '\n'
  for (;;) {
    const char* begin = text_.data() + text_begin_;
    const char* end = text_.data() + text_end_;
    const char* newline = std::find(begin + scanned, end, '\n');
    if (newline != end) {
      const char* stop = (newline > begin && newline[-1] == '\r') ? newline - 1 : newline;
      line->assign(begin, stop);
      text_begin_ = static_cast<std::size_t>(newline - text_.data()) + 1;
      ++line_number_;
      ended_with_newline_ = true;
      return true;
    }
    scanned = text_end_ - text_begin_;
    if (scanned > kMaxLineBytes) Fail("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
    if (!Fill()) {
      if (text_begin_ == text_end_) return false;
      line->assign(text_.data() + text_begin_, text_.data() + text_end_);
      text_begin_ = text_end_;
      ++line_number_;
      ended_with_newline_ = false;
      return true;
    }
  }
}

}  // namespace unimap::io
