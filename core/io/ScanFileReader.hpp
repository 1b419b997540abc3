#pragma once
// Internal to unimap_io: streamed reading of scans.bin.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/DatasetLimits.hpp"
#include "io/ScanRecord.hpp"

namespace unimap::io {

// Reads scans.bin one record at a time through a fixed-size stdio buffer
// plus one reusable payload buffer: memory holds at most one record. Errors
// are InputError "<file>: record <k> (byte <offset>): <reason>", k 1-based.
class ScanFileReader {
 public:
  // Opens the file and checks its header (magic, version 1).
  explicit ScanFileReader(const std::filesystem::path& file);
  ~ScanFileReader();
  ScanFileReader(const ScanFileReader&) = delete;
  ScanFileReader& operator=(const ScanFileReader&) = delete;

  // The next scan; std::nullopt at the end of the file. Throws for a
  // truncated or malformed record, a scan ending before the previous one,
  // or (SetLimits) one the limits find implausible or ending more than
  // max_scan_step_s after the previous one.
  std::optional<ScanRecord> Next();
  // Plausibility limits for the records read next (none by default).
  void SetLimits(const DatasetLimits& limits) { limits_ = limits; }

 private:
  // "<file>: record <k> (byte <offset>)" for the record being read.
  std::string Where() const;

  std::string label_;                    // path as given, for messages
  std::FILE* file_ = nullptr;            // open stream, owned
  std::vector<char> stdio_buffer_;       // buffer handed to setvbuf
  std::uint64_t file_bytes_ = 0;         // size when opened
  std::uint64_t offset_ = 0;             // byte offset of the next record
  std::uint64_t record_ = 0;             // records read so far
  std::vector<unsigned char> payload_;   // reused payload bytes
  double last_end_time_s_ = 0.0;         // ScanEndTime of the previous record
  std::optional<DatasetLimits> limits_;  // plausibility limits, if set
};

}  // namespace unimap::io
