#pragma once
// Internal to unimap_io: the only place that includes PCL (compile time and
// PCL's global definitions stay out of every other file).
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace unimap::io {

// Whether this build can read PCD files (PCL found at configure time).
bool PcdSupported();

// Reads a PCD file's x y z and intensity (0 when the file has no intensity
// field), in file order, into xyzi (one column per point). Non-finite points
// are kept; the caller decides. Throws InputError naming the file when it
// cannot be read or lacks x/y/z, or when the build has no PCD support.
void LoadPcdXyzi(const std::filesystem::path& file, std::vector<Eigen::Vector4f>* xyzi);

}  // namespace unimap::io
