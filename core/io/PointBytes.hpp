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

// Writes every point's record, as append_record produces it, in chunks of a few thousand points.
void WritePointRecords(PartialFile& out, const std::vector<Eigen::Vector3f>& points,
                       const std::function<void(const Eigen::Vector3f&, std::string*)>& append_record);

// Writes 12 bytes (x, y, z as little-endian float32) per point.
void WriteXyzFloat32Le(PartialFile& out, const std::vector<Eigen::Vector3f>& points);

}  // namespace unimap::io
