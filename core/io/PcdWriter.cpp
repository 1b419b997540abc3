#include "io/PcdWriter.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/PartialFile.hpp"

namespace unimap::io {
namespace {

// Points per chunk handed to PartialFile::Write.
constexpr std::size_t kChunkPoints = 4096;

std::string Header(std::size_t points, PcdEncoding encoding) {
  const std::string n = std::to_string(points);
  return "# .PCD v0.7 - Point Cloud Data file format (written by unimap)\n"
         "VERSION 0.7\n"
         "FIELDS x y z\n"
         "SIZE 4 4 4\n"
         "TYPE F F F\n"
         "COUNT 1 1 1\n"
         "WIDTH " + n + "\n"
         "HEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\n"
         "POINTS " + n + "\n"
         "DATA " + (encoding == PcdEncoding::kBinary ? "binary" : "ascii") + "\n";
}

// The IEEE-754 bits of v as 4 little-endian bytes (independent of the host's byte order).
void AppendLittleEndian(float v, std::string* out) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof(bits));
  for (int shift = 0; shift < 32; shift += 8) out->push_back(static_cast<char>((bits >> shift) & 0xFFu));
}

// Shortest text that reads back to the same float ("nan", "inf" for non-finite values).
void AppendText(float v, std::string* out) {
  char text[32];
  const std::to_chars_result r = std::to_chars(text, text + sizeof(text), v);
  out->append(text, r.ptr);
}

}  // namespace

void WritePcdXyz(const std::filesystem::path& file, const std::vector<Eigen::Vector3f>& points_map,
                 PcdEncoding encoding) {
  PartialFile out(file);
  out.Write(Header(points_map.size(), encoding));
  std::string chunk;
  chunk.reserve(kChunkPoints * 48);
  for (std::size_t begin = 0; begin < points_map.size(); begin += kChunkPoints) {
    chunk.clear();
    const std::size_t end = std::min(points_map.size(), begin + kChunkPoints);
    for (std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3f& p = points_map[i];
      if (encoding == PcdEncoding::kBinary) {
        for (int j = 0; j < 3; ++j) AppendLittleEndian(p[j], &chunk);
      } else {
        for (int j = 0; j < 3; ++j) {
          AppendText(p[j], &chunk);
          chunk.push_back(j < 2 ? ' ' : '\n');
        }
      }
    }
    out.Write(chunk);
  }
  out.Commit();
}

}  // namespace unimap::io
