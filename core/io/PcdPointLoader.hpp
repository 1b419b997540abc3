#pragma once
// Internal to unimap_io: PCD point clouds. PcdPointLoader.cpp is the only
// file that includes PCL (compile time and PCL's global definitions stay out
// of every other file).
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace unimap::io {

// Whether this build has PCL (binary_compressed PCD files need it; ascii
// and binary ones are read without it).
bool PcdSupported();

// Reads a PCD file's x y z and intensity (0 when the file has no intensity
// field), in file order, into xyzi (one column per point). Non-finite points
// are kept; the caller decides. The header is checked against the bytes
// present before anything is allocated (PcdHeader). Throws InputError naming
// the file (and, for ascii data, the line) when it cannot be read, lacks
// x/y/z, announces more points than it holds, has a malformed value, or is
// binary_compressed in a build without PCL.
void LoadPcdXyzi(const std::filesystem::path& file, std::vector<Eigen::Vector4f>* xyzi);

}  // namespace unimap::io
