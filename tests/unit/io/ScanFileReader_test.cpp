#include "io/ScanFileReader.hpp"

#include <string>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/ScanCodec.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

RawScan Raw(double start, double end, int points) {
  RawScan raw;
  raw.start_time_s = start;
  raw.end_time_s = end;
  raw.points.resize(static_cast<std::size_t>(points));
  return raw;
}

// A scans.bin holding the given records (already encoded after the header).
std::string FileWith(const std::vector<ScanRecord>& scans) {
  std::string bytes;
  AppendScanFileHeader(&bytes);
  for (const ScanRecord& scan : scans) AppendScanRecord(&bytes, scan);
  return bytes;
}

// Reads every record of `bytes` and returns the InputError message.
std::string ErrorReading(const test::ScratchFolder& folder, const std::string& bytes) {
  test::WriteText(folder / "scans.bin", bytes);
  try {
    ScanFileReader reader(folder / "scans.bin");
    while (reader.Next()) {
    }
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ScanFileReader, TruncatedRecordNamesTheRecord) {
  test::ScratchFolder folder;
  const std::string bytes = FileWith({Raw(0, 1, 3), Raw(1, 2, 3), Raw(2, 3, 3)});
  const std::size_t record = 5 + 21 + 3 * 38;
  // Cut inside the payload of record 3, then inside its 5-byte header.
  std::string error = ErrorReading(folder, bytes.substr(0, bytes.size() - 10));
  EXPECT_TRUE(Contains(error, "scans.bin: record 3 (byte " + std::to_string(12 + 2 * record) + "): truncated"))
      << error;
  error = ErrorReading(folder, bytes.substr(0, 12 + 2 * record + 2));
  EXPECT_TRUE(Contains(error, "record 3") && Contains(error, "truncated")) << error;
}

TEST(ScanFileReader, HugeCountInACorruptHeaderIsTruncationNotAnAllocation) {
  test::ScratchFolder folder;
  std::string bytes = FileWith({Raw(0, 1, 1)});
  bytes[12 + 4] = '\x7f';  // payload size byte 3: ~2 GB announced
  const std::string error = ErrorReading(folder, bytes);
  EXPECT_TRUE(Contains(error, "record 1") && Contains(error, "truncated")) << error;
}

TEST(ScanFileReader, UnknownKindNamesTheRecord) {
  test::ScratchFolder folder;
  std::string bytes = FileWith({Raw(0, 1, 1), Raw(1, 2, 1)});
  bytes[12 + 5 + 21 + 38] = '\x07';
  const std::string error = ErrorReading(folder, bytes);
  EXPECT_TRUE(Contains(error, "scans.bin: record 2") && Contains(error, "unknown record kind 7")) << error;
}

TEST(ScanFileReader, InconsistentPayloadsAreRejected) {
  test::ScratchFolder folder;
  std::string bytes = FileWith({Raw(0, 1, 2)});
  bytes[12 + 5 + 16] = '\x02';  // has_point_time = 2
  EXPECT_TRUE(Contains(ErrorReading(folder, bytes), "has_point_time"));
  bytes = FileWith({Raw(0, 1, 2)});
  bytes[12 + 5 + 17] = '\x03';  // 3 points announced, 2 stored
  EXPECT_TRUE(Contains(ErrorReading(folder, bytes), "record 1"));
  LineScan line;
  line.ranges_m = {1.0f, 2.0f};
  line.intensities = {3.0f, 4.0f};
  bytes = FileWith({line});
  bytes[12 + 5 + 48 + 4 + 8] = '\x01';  // 1 intensity for 2 beams
  EXPECT_TRUE(Contains(ErrorReading(folder, bytes), "1 intensities for 2 beams"));
  bytes = FileWith({Raw(0, 1, 0)});
  bytes[12 + 5 + 7] = '\x40';  // start time 0 becomes 2.0, after the end time 1.0
  EXPECT_TRUE(Contains(ErrorReading(folder, bytes), "ends before it starts"));
}

TEST(ScanFileReader, ScanEndingBeforeThePreviousOneIsRejected) {
  test::ScratchFolder folder;
  const std::string error = ErrorReading(folder, FileWith({Raw(0, 2, 1), Raw(0.5, 1, 1)}));
  EXPECT_TRUE(Contains(error, "record 2") && Contains(error, "time goes backwards")) << error;
}

TEST(ScanFileReader, BadHeadersAreRejected) {
  test::ScratchFolder folder;
  EXPECT_TRUE(Contains(ErrorReading(folder, "UNIMAP"), "too short"));
  EXPECT_TRUE(Contains(ErrorReading(folder, std::string("UNIMAPXX\x01\0\0\0", 12)), "magic"));
  EXPECT_TRUE(Contains(ErrorReading(folder, std::string("UNIMAPSC\x02\0\0\0", 12)), "version 2 is not supported"));
}

TEST(ScanFileReader, EmptyFileWithHeaderHasNoScans) {
  test::ScratchFolder folder;
  test::WriteText(folder / "scans.bin", FileWith({}));
  ScanFileReader reader(folder / "scans.bin");
  EXPECT_FALSE(reader.Next());
}

}  // namespace
}  // namespace unimap::io
