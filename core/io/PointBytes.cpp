#include "io/PointBytes.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace unimap::io {
namespace {

// Points per chunk handed to PartialFile::Write.
constexpr std::size_t kChunkPoints = 4096;

}  // namespace

void AppendFloat32Le(float v, std::string* out) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof(bits));
  for (int shift = 0; shift < 32; shift += 8) out->push_back(static_cast<char>((bits >> shift) & 0xFFu));
}

void WritePointRecords(PartialFile& out, std::size_t points,
                       const std::function<void(std::size_t, std::string*)>& append_record) {
  std::string chunk;
  for (std::size_t begin = 0; begin < points; begin += kChunkPoints) {
    chunk.clear();
    const std::size_t end = std::min(points, begin + kChunkPoints);
    for (std::size_t i = begin; i < end; ++i) append_record(i, &chunk);
    out.Write(chunk);
  }
}

void WriteXyzFloat32Le(PartialFile& out, const std::vector<Eigen::Vector3f>& points,
                       const std::vector<float>* intensities) {
  WritePointRecords(out, points.size(), [&](std::size_t i, std::string* record) {
    for (int j = 0; j < 3; ++j) AppendFloat32Le(points[i][j], record);
    if (intensities != nullptr) AppendFloat32Le((*intensities)[i], record);
  });
}

}  // namespace unimap::io
