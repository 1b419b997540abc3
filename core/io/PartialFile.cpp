#include "io/PartialFile.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>
#include <utility>

#include <unistd.h>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{256} << 10;

std::string Reason() { return std::strerror(errno); }

}  // namespace

PartialFile::PartialFile(std::filesystem::path final_path) : final_path_(std::move(final_path)), buffer_(kBufferBytes) {
  partial_path_ = final_path_;
  partial_path_ += kSuffix;
  stream_ = std::fopen(partial_path_.c_str(), "wb");
  if (stream_ == nullptr) {
    throw InputError(partial_path_.string() + ": cannot create: " + Reason());
  }
  std::setvbuf(stream_, buffer_.data(), _IOFBF, buffer_.size());
}

PartialFile::~PartialFile() {
  if (stream_ == nullptr) return;
  std::fclose(stream_);
  std::error_code ignored;  // nothing to report from a destructor
  std::filesystem::remove(partial_path_, ignored);
}

void PartialFile::Write(const void* data, std::size_t size) {
  if (stream_ == nullptr) {
    throw InputError(final_path_.string() + ": write after the file was completed");
  }
  if (size > 0 && std::fwrite(data, 1, size, stream_) != size) {
    throw InputError(partial_path_.string() + ": write failed: " + Reason());
  }
}

void PartialFile::Commit() {
  if (stream_ == nullptr) {
    throw InputError(final_path_.string() + ": completed twice");
  }
  std::FILE* stream = stream_;
  stream_ = nullptr;
  const bool flushed = std::fflush(stream) == 0 && ::fsync(::fileno(stream)) == 0;
  const std::string flush_reason = flushed ? std::string() : Reason();
  const bool closed = std::fclose(stream) == 0;
  if (!flushed || !closed) {
    throw InputError(partial_path_.string() + ": cannot complete the file: " + (flushed ? Reason() : flush_reason));
  }
  std::error_code ec;
  std::filesystem::rename(partial_path_, final_path_, ec);
  if (ec) {
    throw InputError(partial_path_.string() + ": cannot rename to " + final_path_.string() + ": " + ec.message());
  }
}

void WriteWholeFile(const std::filesystem::path& file, const std::function<void(PartialFile&)>& write) {
  std::filesystem::path partial_path;
  try {
    PartialFile out(file);
    partial_path = out.partial_path();
    write(out);
    out.Commit();
  } catch (...) {
    std::error_code ignored;
    if (!partial_path.empty()) std::filesystem::remove(partial_path, ignored);
    throw;
  }
}

}  // namespace unimap::io
