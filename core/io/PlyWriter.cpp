#include "io/PlyWriter.hpp"

#include <string>

#include "io/PartialFile.hpp"
#include "io/PointBytes.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

std::string Header(std::size_t points, bool intensity) {
  return "ply\n"
         "format binary_little_endian 1.0\n"
         "comment written by unimap\n"
         "element vertex " +
         std::to_string(points) +
         "\n"
         "property float x\n"
         "property float y\n"
         "property float z\n" +
         std::string(intensity ? "property float intensity\n" : "") + "end_header\n";
}

}  // namespace

void WritePly(const std::filesystem::path& file, const std::vector<Eigen::Vector3f>& points_map,
              const std::vector<float>* intensities) {
  if (intensities != nullptr && intensities->size() != points_map.size()) {
    throw InputError(file.string() + ": " + std::to_string(intensities->size()) + " intensities for " +
                     std::to_string(points_map.size()) + " points");
  }
  // Checked before anything is created, so a rejected cloud leaves no file.
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    if (!points_map[i].allFinite()) {
      throw InputError(file.string() + ": point " + std::to_string(i) + " is not finite (PLY map points must be)");
    }
  }
  WriteWholeFile(file, [&](PartialFile& out) {
    out.Write(Header(points_map.size(), intensities != nullptr));
    WriteXyzFloat32Le(out, points_map, intensities);
  });
}

}  // namespace unimap::io
