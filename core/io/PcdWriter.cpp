#include "io/PcdWriter.hpp"

#include <charconv>
#include <string>

#include "io/PartialFile.hpp"
#include "io/PointBytes.hpp"

namespace unimap::io {
namespace {

std::string Header(std::size_t points, PcdEncoding encoding) {
  const std::string n = std::to_string(points);
  return "# .PCD v0.7 - Point Cloud Data file format (written by unimap)\n"
         "VERSION 0.7\n"
         "FIELDS x y z\n"
         "SIZE 4 4 4\n"
         "TYPE F F F\n"
         "COUNT 1 1 1\n"
         "WIDTH " +
         n +
         "\n"
         "HEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\n"
         "POINTS " +
         n +
         "\n"
         "DATA " +
         (encoding == PcdEncoding::kBinary ? "binary" : "ascii") + "\n";
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
  WriteWholeFile(file, [&](PartialFile& out) {
    out.Write(Header(points_map.size(), encoding));
    if (encoding == PcdEncoding::kBinary) {
      WriteXyzFloat32Le(out, points_map);
    } else {
      WritePointRecords(out, points_map, [](const Eigen::Vector3f& p, std::string* record) {
        for (int j = 0; j < 3; ++j) {
          AppendText(p[j], record);
          record->push_back(j < 2 ? ' ' : '\n');
        }
      });
    }
  });
}

}  // namespace unimap::io
