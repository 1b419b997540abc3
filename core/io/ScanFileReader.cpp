#include "io/ScanFileReader.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/NumberText.hpp"
#include "io/ScanCodec.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kStdioBufferBytes = std::size_t{256} << 10;

std::string Text(double value) {
  std::string out;
  AppendNumber(&out, value);
  return out;
}

}  // namespace

ScanFileReader::ScanFileReader(const std::filesystem::path& file)
    : label_(file.string()), stdio_buffer_(kStdioBufferBytes) {
  std::error_code ec;
  file_bytes_ = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(label_ + ": cannot open for reading: " + ec.message());
  file_ = std::fopen(label_.c_str(), "rb");
  if (file_ == nullptr) {
    throw InputError(label_ + ": cannot open for reading: " + std::strerror(errno));
  }
  std::setvbuf(file_, stdio_buffer_.data(), _IOFBF, stdio_buffer_.size());
  unsigned char header[kScanFileHeaderBytes];
  if (std::fread(header, 1, sizeof(header), file_) != sizeof(header)) {
    std::fclose(file_);
    throw InputError(label_ + ": too short for the file header (8-byte magic + u32 version)");
  }
  if (std::memcmp(header, kScanFileMagic, sizeof(kScanFileMagic)) != 0) {
    std::fclose(file_);
    throw InputError(label_ + ": not a unimap scan file (the magic is not UNIMAPSC)");
  }
  const std::uint32_t version = LoadU32(header + sizeof(kScanFileMagic));
  if (version != kScanFileVersion) {
    std::fclose(file_);
    throw InputError(label_ + ": scan file version " + std::to_string(version) +
                     " is not supported (this build reads version " + std::to_string(kScanFileVersion) + ")");
  }
  offset_ = kScanFileHeaderBytes;
}

ScanFileReader::~ScanFileReader() { std::fclose(file_); }

std::string ScanFileReader::Where() const {
  return label_ + ": record " + std::to_string(record_ + 1) + " (byte " + std::to_string(offset_) + ")";
}

std::optional<ScanRecord> ScanFileReader::Next() {
  unsigned char header[kScanRecordHeaderBytes];
  const std::size_t got = std::fread(header, 1, sizeof(header), file_);
  if (got == 0 && std::feof(file_) != 0) return std::nullopt;
  if (std::ferror(file_) != 0) throw InputError(Where() + ": read error");
  if (got < sizeof(header)) {
    throw InputError(Where() + ": truncated: only " + std::to_string(got) +
                     " of the 5 record header bytes are present");
  }
  const std::uint8_t kind = header[0];
  const std::uint32_t size = LoadU32(header + 1);
  const std::uint64_t left = file_bytes_ > offset_ + sizeof(header) ? file_bytes_ - offset_ - sizeof(header) : 0;
  if (size > left) {  // checked before allocating: a corrupt count cannot exhaust memory
    throw InputError(Where() + ": truncated: its header announces " + std::to_string(size) + " payload bytes, only " +
                     std::to_string(left) + " remain in the file");
  }
  payload_.resize(size);
  const std::size_t read = std::fread(payload_.data(), 1, size, file_);
  if (read != size) {
    if (std::ferror(file_) != 0) throw InputError(Where() + ": read error");
    throw InputError(Where() + ": truncated: its header announces " + std::to_string(size) + " payload bytes, only " +
                     std::to_string(read) + " could be read");
  }
  ScanRecord scan = DecodeScanPayload(kind, payload_.data(), size, Where());
  const double end_time_s = ScanEndTime(scan);
  if (record_ > 0 && end_time_s < last_end_time_s_) {
    throw InputError(Where() + ": time goes backwards: the scan ends at " + Text(end_time_s) +
                     " s, the previous one at " + Text(last_end_time_s_) + " s");
  }
  if (limits_) {
    const std::string problem = limits_->ScanProblem(scan);
    if (!problem.empty()) throw InputError(Where() + ": " + problem);
    if (record_ > 0 && end_time_s - last_end_time_s_ > limits_->max_scan_step_s) {
      throw InputError(Where() + ": time jumps " + Text(end_time_s - last_end_time_s_) + " s ahead (the scan ends at " +
                       Text(end_time_s) + " s, the previous one at " + Text(last_end_time_s_) + " s), more than the " +
                       Text(limits_->max_scan_step_s) +
                       " s a scan may follow the previous one: a clock jump or lost data");
    }
  }
  last_end_time_s_ = end_time_s;
  offset_ += sizeof(header) + size;
  ++record_;
  return scan;
}

}  // namespace unimap::io
