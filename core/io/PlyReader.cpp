#include "io/PlyReader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "io/NumberText.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

enum class Format { kAscii, kLittleEndian, kBigEndian };

// Scalar property kinds; the byte count is kBytes[kind].
enum Kind { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
constexpr std::array<std::size_t, 8> kBytes = {1, 1, 2, 2, 4, 4, 4, 8};

// Vertices decoded per binary read.
constexpr std::size_t kChunkVertices = 4096;

// What the header says about the vertex element.
struct VertexLayout {
  Format format = Format::kAscii;
  std::size_t count = 0;                  // vertices announced
  std::vector<Kind> kinds;                // one per property, in order
  std::array<int, 3> xyz = {-1, -1, -1};  // property index of x, y, z
  std::size_t stride = 0;                 // bytes per binary vertex
  std::size_t header_lines = 0;           // lines up to and including end_header
};

[[noreturn]] void Fail(const std::filesystem::path& file, const std::string& reason) {
  throw InputError(file.string() + ": " + reason);
}

bool KindOf(const std::string& name, Kind* kind) {
  static const std::pair<const char*, Kind> kNames[] = {
      {"char", kInt8},     {"int8", kInt8},       {"uchar", kUint8},    {"uint8", kUint8},
      {"short", kInt16},   {"int16", kInt16},     {"ushort", kUint16},  {"uint16", kUint16},
      {"int", kInt32},     {"int32", kInt32},     {"uint", kUint32},    {"uint32", kUint32},
      {"float", kFloat32}, {"float32", kFloat32}, {"double", kFloat64}, {"float64", kFloat64}};
  for (const auto& entry : kNames) {
    if (name == entry.first) {
      *kind = entry.second;
      return true;
    }
  }
  return false;
}

// Parses the header up to and including "end_header".
VertexLayout ReadHeader(const std::filesystem::path& file, std::istream& in) {
  std::string line;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) Fail(file, "not a PLY file (no 'ply' line)");
  VertexLayout layout;
  layout.header_lines = 1;
  bool has_format = false;
  std::string element;  // current element name; "" before the first
  bool vertex_seen = false;
  while (std::getline(in, line)) {
    ++layout.header_lines;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") {
      if (!has_format) Fail(file, "PLY header has no format line");
      if (!vertex_seen) Fail(file, "PLY header has no vertex element");
      for (int axis = 0; axis < 3; ++axis) {
        if (layout.xyz[static_cast<std::size_t>(axis)] < 0) {
          Fail(file, std::string("PLY vertex element has no property ") + "xyz"[axis]);
        }
      }
      return layout;
    }
    if (word == "format") {
      std::string name, version;
      words >> name >> version;
      if (version != "1.0") Fail(file, "unsupported PLY version '" + version + "'");
      if (name == "ascii")
        layout.format = Format::kAscii;
      else if (name == "binary_little_endian")
        layout.format = Format::kLittleEndian;
      else if (name == "binary_big_endian")
        layout.format = Format::kBigEndian;
      else
        Fail(file, "unsupported PLY format '" + name + "'");
      has_format = true;
    } else if (word == "element") {
      std::string count_text;
      words >> element >> count_text;
      if (!vertex_seen && element != "vertex") Fail(file, "PLY element '" + element + "' before the vertex element");
      if (element == "vertex") {
        const char* end = count_text.data() + count_text.size();
        const std::from_chars_result r = std::from_chars(count_text.data(), end, layout.count);
        if (vertex_seen || count_text.empty() || r.ec != std::errc() || r.ptr != end) {
          Fail(file, "bad PLY vertex element '" + line + "'");
        }
        vertex_seen = true;
      }
    } else if (word == "property" && element == "vertex") {
      std::string type, name;
      words >> type >> name;
      Kind kind = kFloat32;
      if (type == "list") Fail(file, "PLY vertex element has a list property");
      if (!KindOf(type, &kind) || name.empty()) Fail(file, "bad PLY property line '" + line + "'");
      for (int axis = 0; axis < 3; ++axis) {
        if (name == std::string(1, "xyz"[axis]))
          layout.xyz[static_cast<std::size_t>(axis)] = static_cast<int>(layout.kinds.size());
      }
      layout.kinds.push_back(kind);
      layout.stride += kBytes[kind];
    } else if (word != "property" && word != "comment" && word != "obj_info" && !word.empty()) {
      Fail(file, "unknown PLY header line '" + line + "'");
    }
  }
  Fail(file, "PLY header has no end_header line");
}

// The value of one binary scalar of the given kind starting at bytes.
double Decode(const unsigned char* bytes, Kind kind, Format format) {
  const std::size_t n = kBytes[kind];
  std::uint64_t bits = 0;
  for (std::size_t b = 0; b < n; ++b) {
    const std::size_t shift = format == Format::kLittleEndian ? b : n - 1 - b;
    bits |= static_cast<std::uint64_t>(bytes[b]) << (8 * shift);
  }
  switch (kind) {
    case kInt8:
      return static_cast<std::int8_t>(static_cast<std::uint8_t>(bits));
    case kUint8:
      return static_cast<double>(bits);
    case kInt16:
      return static_cast<std::int16_t>(static_cast<std::uint16_t>(bits));
    case kUint16:
      return static_cast<double>(bits);
    case kInt32:
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(bits));
    case kUint32:
      return static_cast<double>(bits);
    case kFloat32: {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float v = 0.0f;
      std::memcpy(&v, &narrow, sizeof(v));
      return v;
    }
    case kFloat64: {
      double v = 0.0;
      std::memcpy(&v, &bits, sizeof(v));
      return v;
    }
  }
  return 0.0;
}

void ReadBinary(const std::filesystem::path& file, std::istream& in, const VertexLayout& layout,
                std::vector<Eigen::Vector3f>* points) {
  std::vector<std::size_t> offsets(layout.kinds.size());
  for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] = offsets[i - 1] + kBytes[layout.kinds[i - 1]];
  std::vector<unsigned char> chunk;
  for (std::size_t begin = 0; begin < layout.count; begin += kChunkVertices) {
    const std::size_t n = std::min(kChunkVertices, layout.count - begin);
    chunk.resize(n * layout.stride);
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(chunk.size()));
    if (static_cast<std::size_t>(in.gcount()) != chunk.size()) {
      Fail(file, "PLY data ends after " +
                     std::to_string(begin + static_cast<std::size_t>(in.gcount()) / layout.stride) + " of " +
                     std::to_string(layout.count) + " vertices");
    }
    for (std::size_t v = 0; v < n; ++v) {
      Eigen::Vector3f p;
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const auto property = static_cast<std::size_t>(layout.xyz[axis]);
        p[static_cast<Eigen::Index>(axis)] = static_cast<float>(
            Decode(&chunk[v * layout.stride + offsets[property]], layout.kinds[property], layout.format));
      }
      points->push_back(p);
    }
  }
}

void ReadAscii(const std::filesystem::path& file, std::istream& in, const VertexLayout& layout,
               std::vector<Eigen::Vector3f>* points) {
  std::string line;
  std::size_t line_number = layout.header_lines;
  std::vector<double> values(layout.kinds.size());
  while (points->size() < layout.count) {
    if (!std::getline(in, line)) {
      Fail(file, "PLY data ends after " + std::to_string(points->size()) + " of " + std::to_string(layout.count) +
                     " vertices");
    }
    ++line_number;
    std::istringstream words(line);
    std::string word;
    for (double& value : values) {
      if (!(words >> word) || !ParseNumber(word, &value)) {
        Fail(file, std::to_string(line_number) + ": expected " + std::to_string(values.size()) + " numbers");
      }
    }
    points->emplace_back(static_cast<float>(values[static_cast<std::size_t>(layout.xyz[0])]),
                         static_cast<float>(values[static_cast<std::size_t>(layout.xyz[1])]),
                         static_cast<float>(values[static_cast<std::size_t>(layout.xyz[2])]));
  }
}

}  // namespace

std::vector<Eigen::Vector3f> ReadPlyVertices(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) Fail(file, "cannot open");
  const VertexLayout layout = ReadHeader(file, in);
  std::vector<Eigen::Vector3f> points;
  // Never trust the announced count for the allocation (a corrupt header).
  points.reserve(std::min<std::size_t>(layout.count, std::size_t{1} << 20));
  if (layout.format == Format::kAscii) {
    ReadAscii(file, in, layout, &points);
  } else {
    ReadBinary(file, in, layout, &points);
  }
  return points;
}

}  // namespace unimap::io
