#pragma once
// Internal to unimap_io: the text header of a PCD file, read and checked
// before any point is allocated.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace unimap::io {

// One FIELDS entry of a PCD header.
struct PcdField {
  std::string name;        // e.g. "x"
  std::size_t size = 4;    // bytes per value: 1, 2, 4 or 8
  char type = 'F';         // 'F' float, 'I' signed, 'U' unsigned
  std::size_t count = 1;   // values per point
  std::size_t offset = 0;  // bytes from the start of a binary point
};

// What the header says; every count is checked against its neighbours and
// (CheckPcdDataSize) against the bytes that follow it.
struct PcdHeader {
  std::vector<PcdField> fields;   // in file order
  std::uint64_t width = 0;        // WIDTH
  std::uint64_t height = 0;       // HEIGHT
  std::uint64_t points = 0;       // POINTS (= width * height)
  std::string data;               // "ascii", "binary" or "binary_compressed"
  std::uint64_t data_offset = 0;  // first byte after the DATA line
  std::int64_t data_line = 0;     // 1-based line number of the DATA line
  std::size_t point_bytes = 0;    // sum of size * count: one binary point

  // The field named `name`, or nullptr.
  const PcdField* Find(const std::string& name) const;
  // Values per point in an ascii line (sum of the counts).
  std::size_t ValuesPerPoint() const;
};

// Reads and checks the header; throws InputError "<file>:<line>: <reason>"
// for a missing or malformed line (FIELDS / SIZE / TYPE / COUNT disagreeing,
// a size other than 1, 2, 4, 8, POINTS other than WIDTH x HEIGHT, an unknown
// DATA kind, a header longer than 64 KiB).
PcdHeader ReadPcdHeader(const std::filesystem::path& file);

// Throws InputError naming the file when the bytes after the header cannot
// hold the points announced (binary: points x point_bytes; ascii: at least
// two bytes per point; binary_compressed: the compressed block must fit and
// expand to points x point_bytes, at most 88 times its size, LZF's limit).
void CheckPcdDataSize(const std::filesystem::path& file, const PcdHeader& header, std::uint64_t file_bytes);

}  // namespace unimap::io
