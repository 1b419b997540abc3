#include "io/PcdPointLoader.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string_view>
#include <system_error>

#include "io/LineReader.hpp"
#include "io/NumberText.hpp"
#include "io/PcdHeader.hpp"
#include "unimap/Errors.hpp"

#if UNIMAP_WITH_PCL
#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#endif

namespace unimap::io {
namespace {

constexpr std::size_t kChunkPoints = 4096;  // binary points decoded per read

// Index of x, y, z and intensity among the ascii values of a point (the
// first value of each field).
struct XyziColumns {
  std::size_t column[4] = {0, 0, 0, 0};
  bool has_intensity = false;
};

XyziColumns ColumnsOf(const PcdHeader& header) {
  XyziColumns columns;
  std::size_t value = 0;
  for (const PcdField& field : header.fields) {
    const char* names[4] = {"x", "y", "z", "intensity"};
    for (std::size_t k = 0; k < 4; ++k) {
      if (field.name == names[k]) columns.column[k] = value;
    }
    if (field.name == "intensity") columns.has_intensity = true;
    value += field.count;
  }
  return columns;
}

// One binary value as a double (little-endian, as PCL writes on x86).
double Decode(const unsigned char* bytes, const PcdField& field) {
  std::uint64_t bits = 0;
  for (std::size_t b = 0; b < field.size; ++b) bits |= std::uint64_t{bytes[b]} << (8 * b);
  if (field.type == 'F') {
    if (field.size == 4) {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float v = 0.0f;
      std::memcpy(&v, &narrow, sizeof(v));
      return v;
    }
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
  }
  if (field.type == 'U') return static_cast<double>(bits);
  const unsigned shift = static_cast<unsigned>(64 - 8 * field.size);  // sign-extend
  return static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
}

// Reads the ascii data lines, naming the line of any malformed value.
void ReadAscii(const std::filesystem::path& file, const PcdHeader& header, std::vector<Eigen::Vector4f>* xyzi) {
  const XyziColumns columns = ColumnsOf(header);
  const std::size_t values_per_point = header.ValuesPerPoint();
  std::vector<double> values(values_per_point);
  LineReader lines(file);
  std::string_view line;
  while (lines.line_number() < header.data_line && lines.Next(&line)) {
  }
  const std::string where = lines.label() + ":";
  while (lines.Next(&line)) {
    const std::string at = where + std::to_string(lines.line_number()) + ": ";
    std::size_t count = 0, pos = 0;
    while (pos < line.size()) {
      while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t' || line[pos] == '\r')) ++pos;
      if (pos == line.size()) break;
      std::size_t end = pos;
      while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
      const std::string_view word = line.substr(pos, end - pos);
      if (count == values_per_point) {
        throw InputError(at + "a point needs " + std::to_string(values_per_point) + " values, found more");
      }
      if (!ParseNumber(word, &values[count])) {
        throw InputError(at + "value " + std::to_string(count + 1) + " '" + std::string(word.substr(0, 40)) +
                         "' is not a number");
      }
      ++count;
      pos = end;
    }
    if (count == 0) continue;  // a blank line
    if (count != values_per_point) {
      throw InputError(at + "a point needs " + std::to_string(values_per_point) + " values, found " +
                       std::to_string(count));
    }
    if (xyzi->size() == header.points) {
      throw InputError(at + "more points than the " + std::to_string(header.points) + " the header announces");
    }
    xyzi->emplace_back(static_cast<float>(values[columns.column[0]]), static_cast<float>(values[columns.column[1]]),
                       static_cast<float>(values[columns.column[2]]),
                       columns.has_intensity ? static_cast<float>(values[columns.column[3]]) : 0.0f);
  }
  if (xyzi->size() != header.points) {
    throw InputError(file.string() + ": the data ends after " + std::to_string(xyzi->size()) + " of the " +
                     std::to_string(header.points) + " points the header announces");
  }
}

// Decodes the binary points (their count was checked against the file size).
void ReadBinary(const std::filesystem::path& file, const PcdHeader& header, std::vector<Eigen::Vector4f>* xyzi) {
  const PcdField* fields[4] = {header.Find("x"), header.Find("y"), header.Find("z"), header.Find("intensity")};
  std::ifstream in(file, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.data_offset));
  std::vector<unsigned char> chunk;
  xyzi->reserve(header.points);
  for (std::uint64_t begin = 0; begin < header.points; begin += kChunkPoints) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkPoints, header.points - begin));
    chunk.resize(n * header.point_bytes);
    if (!in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(chunk.size()))) {
      throw InputError(file.string() + ": short read (the file changed or is damaged)");
    }
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* point = chunk.data() + i * header.point_bytes;
      Eigen::Vector4f p = Eigen::Vector4f::Zero();
      for (int k = 0; k < 4; ++k) {
        if (fields[k] != nullptr) p[k] = static_cast<float>(Decode(point + fields[k]->offset, *fields[k]));
      }
      xyzi->push_back(p);
    }
  }
}

}  // namespace

#if UNIMAP_WITH_PCL

bool PcdSupported() { return true; }

namespace {

// binary_compressed data through PCL (LZF, fields stored one after another).
void ReadCompressed(const std::filesystem::path& file, const PcdHeader& header, std::vector<Eigen::Vector4f>* xyzi) {
  for (const char* name : {"x", "y", "z", "intensity"}) {
    const PcdField* field = header.Find(name);
    if (field != nullptr && (field->type != 'F' || field->size != 4 || field->count != 1)) {
      throw InputError(file.string() + ": binary_compressed field " + name +
                       " is not one 4-byte float (not supported)");
    }
  }
  pcl::PCDReader reader;
  pcl::PointCloud<pcl::PointXYZI> cloud;
  if (reader.read(file.string(), cloud) != 0) {
    throw InputError(file.string() + ": PCD data cannot be read (damaged or truncated)");
  }
  xyzi->reserve(cloud.size());
  for (const pcl::PointXYZI& p : cloud.points) {
    xyzi->emplace_back(p.x, p.y, p.z, header.Find("intensity") != nullptr ? p.intensity : 0.0f);
  }
}

}  // namespace

#else

bool PcdSupported() { return false; }

namespace {

void ReadCompressed(const std::filesystem::path& file, const PcdHeader& /*header*/,
                    std::vector<Eigen::Vector4f>* /*xyzi*/) {
  throw InputError(file.string() +
                   ": binary_compressed PCD needs PCL, which this build of unimap lacks (not found at configure time)");
}

}  // namespace

#endif

void LoadPcdXyzi(const std::filesystem::path& file, std::vector<Eigen::Vector4f>* xyzi) {
  const std::string name = file.string();
  std::error_code ec;
  const std::uint64_t bytes = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(name + ": cannot read: " + ec.message());
  // The header is checked against the bytes present before anything is
  // allocated: a corrupt POINTS line cannot exhaust memory.
  const PcdHeader header = ReadPcdHeader(file);
  for (const char* axis : {"x", "y", "z"}) {
    if (header.Find(axis) == nullptr) throw InputError(name + ": PCD file has no " + axis + " field");
  }
  CheckPcdDataSize(file, header, bytes);
  xyzi->clear();
  if (header.data == "ascii") {
    ReadAscii(file, header, xyzi);
  } else if (header.data == "binary") {
    ReadBinary(file, header, xyzi);
  } else {
    ReadCompressed(file, header, xyzi);
  }
}

}  // namespace unimap::io
