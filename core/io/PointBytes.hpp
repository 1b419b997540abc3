#pragma once
// Internal to unimap_io: point records written in chunks, e.g. the
// little-endian float32 x y z body of binary PCD and PLY files.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/PartialFile.hpp"

namespace unimap::io {

// Appends the IEEE-754 bits of v as 4 little-endian bytes (independent of the host's byte order).
void AppendFloat32Le(float v, std::string* out);

// Writes every point's record, as append_record(index, out) produces it, in chunks of a few thousand points.
void WritePointRecords(PartialFile& out, std::size_t points,
                       const std::function<void(std::size_t, std::string*)>& append_record);

// Writes 12 bytes (x, y, z as little-endian float32) per point; with
// intensities (one per point), 16 (x, y, z, intensity).
void WriteXyzFloat32Le(PartialFile& out, const std::vector<Eigen::Vector3f>& points,
                       const std::vector<float>* intensities = nullptr);

}  // namespace unimap::io
