#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::matching {

// Keeps one point per voxel (the first one seen, so the result is
// deterministic and a real measurement), then at most max_points of them
// chosen with a seeded generator (0 = keep all).
std::vector<Eigen::Vector3f> VoxelDownsample(const std::vector<Eigen::Vector3f>& points, double voxel_m,
                                             int max_points, std::uint64_t seed);

}  // namespace unimap::matching
