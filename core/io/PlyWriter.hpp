#pragma once
// Writes point clouds as binary PLY files (the format MeshLab, CloudCompare,
// Open3D and Blender read): one "vertex" element with float x y z (and intensity).
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace unimap::io {

// Writes points_map (in order) to file atomically ("<file>.partial" written,
// then renamed into place by io::PartialFile). The header is exactly
//   ply
//   format binary_little_endian 1.0
//   comment written by unimap
//   element vertex <n>
//   property float x
//   property float y
//   property float z
//   end_header
// followed by n x 12 bytes: x y z as little-endian IEEE-754 float32. With
// intensities (one per point) the header also has "property float
// intensity" after z and each point 16 bytes (InputError when their count
// is not the points').
// Non-finite points are rejected, not skipped: a map holding NaN or infinity
// is a bug upstream, and a silently shorter file would hide it. Throws
// InputError naming the file (and, for a non-finite point, its index) when
// the file cannot be written or a point is not finite; no <file> and no
// "<file>.partial" is left behind then.
void WritePly(const std::filesystem::path& file, const std::vector<Eigen::Vector3f>& points_map,
              const std::vector<float>* intensities = nullptr);

}  // namespace unimap::io
