#pragma once
// Writes point clouds as PCD v0.7 files (the format PCL, CloudCompare and
// `unimap localize` read) without PCL: FIELDS x y z, float32, unorganised.
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace unimap::io {

// How the point data follows the header.
enum class PcdEncoding {
  kBinary,  // "DATA binary": x y z as little-endian float32, 12 bytes per point (compact, fast)
  kAscii,   // "DATA ascii": one "x y z" line per point, shortest round-trip text (exact)
};

// Writes points_map (in order), with intensities (one per point; FIELDS
// x y z intensity, float32) when given, to file atomically: "<file>.partial" is
// written and renamed into place (io::WriteWholeFile), so a failed write
// never leaves a file that looks complete, nor the ".partial". The header is
//   VERSION 0.7, FIELDS x y z, SIZE 4 4 4, TYPE F F F, COUNT 1 1 1,
//   WIDTH n, HEIGHT 1, VIEWPOINT 0 0 0 1 0 0 0, POINTS n, DATA binary|ascii.
// Non-finite points are written as they are (PCD allows NaN). Throws
// InputError naming the file when it cannot be written.
// InputError too when intensities are given and not one per point.
void WritePcdXyz(const std::filesystem::path& file, const std::vector<Eigen::Vector3f>& points_map,
                 PcdEncoding encoding = PcdEncoding::kBinary, const std::vector<float>* intensities = nullptr);

}  // namespace unimap::io
