#pragma once
// Reads the vertex positions of a PLY point cloud (the maps WritePly writes,
// and the common variants other tools write).
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace unimap::io {

// Reads x y z of every vertex, in file order. Accepted: format ascii,
// binary_little_endian or binary_big_endian 1.0; "element vertex N" as the
// first element, with scalar properties of any PLY type (char/int8, uchar/
// uint8, short/int16, ushort/uint16, int/int32, uint/uint32, float/float32,
// double/float64) among which x, y and z; other vertex properties are
// skipped, later elements (faces, ...) are ignored. Values are converted to
// float; non-finite values are kept (the caller decides). Throws InputError
// naming the file (and, for ascii data, the line) when it cannot be opened,
// is not PLY, uses another format, has no vertex element, a list property
// in it, no x/y/z, a malformed number or fewer vertices than announced.
std::vector<Eigen::Vector3f> ReadPlyVertices(const std::filesystem::path& file);

}  // namespace unimap::io
