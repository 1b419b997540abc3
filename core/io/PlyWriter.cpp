#include "io/PlyWriter.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/PartialFile.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Points per chunk handed to PartialFile::Write.
constexpr std::size_t kChunkPoints = 4096;

std::string Header(std::size_t points) {
  return "ply\n"
         "format binary_little_endian 1.0\n"
         "comment written by unimap\n"
         "element vertex " + std::to_string(points) + "\n"
         "property float x\n"
         "property float y\n"
         "property float z\n"
         "end_header\n";
}

// The IEEE-754 bits of v as 4 little-endian bytes (independent of the host's byte order).
void AppendLittleEndian(float v, std::string* out) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof(bits));
  for (int shift = 0; shift < 32; shift += 8) out->push_back(static_cast<char>((bits >> shift) & 0xFFu));
}

}  // namespace

void WritePly(const std::filesystem::path& file, const std::vector<Eigen::Vector3f>& points_map) {
  // Checked before anything is created, so a rejected cloud leaves no file.
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    if (!points_map[i].allFinite()) {
      throw InputError(file.string() + ": point " + std::to_string(i) + " is not finite (PLY map points must be)");
    }
  }
  WriteWholeFile(file, [&](PartialFile& out) {
    out.Write(Header(points_map.size()));
    std::string chunk;
    chunk.reserve(kChunkPoints * 12);
    for (std::size_t begin = 0; begin < points_map.size(); begin += kChunkPoints) {
      chunk.clear();
      const std::size_t end = std::min(points_map.size(), begin + kChunkPoints);
      for (std::size_t i = begin; i < end; ++i) {
        for (int j = 0; j < 3; ++j) AppendLittleEndian(points_map[i][j], &chunk);
      }
      out.Write(chunk);
    }
  });
}

}  // namespace unimap::io
