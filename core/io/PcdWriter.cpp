#include "io/PcdWriter.hpp"

#include <charconv>
#include <string>

#include "io/PartialFile.hpp"
#include "io/PointBytes.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

std::string Header(std::size_t points, PcdEncoding encoding, bool intensity) {
  const std::string n = std::to_string(points);
  return std::string(
             "# .PCD v0.7 - Point Cloud Data file format (written by unimap)\n"
             "VERSION 0.7\n") +
         (intensity ? "FIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
                    : "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n") +
         "WIDTH " + n +
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
                 PcdEncoding encoding, const std::vector<float>* intensities) {
  if (intensities != nullptr && intensities->size() != points_map.size()) {
    throw InputError(file.string() + ": " + std::to_string(intensities->size()) + " intensities for " +
                     std::to_string(points_map.size()) + " points");
  }
  WriteWholeFile(file, [&](PartialFile& out) {
    out.Write(Header(points_map.size(), encoding, intensities != nullptr));
    if (encoding == PcdEncoding::kBinary) {
      WriteXyzFloat32Le(out, points_map, intensities);
    } else {
      WritePointRecords(out, points_map.size(), [&](std::size_t i, std::string* record) {
        for (int j = 0; j < 3; ++j) {
          AppendText(points_map[i][j], record);
          record->push_back(j < 2 || intensities != nullptr ? ' ' : '\n');
        }
        if (intensities != nullptr) {
          AppendText((*intensities)[i], record);
          record->push_back('\n');
        }
      });
    }
  });
}

}  // namespace unimap::io
