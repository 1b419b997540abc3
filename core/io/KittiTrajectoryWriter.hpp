#pragma once
// Trajectories in the KITTI odometry pose format (what the KITTI devkit and
// evo's `evo_traj kitti` read).
#include <filesystem>
#include <vector>

#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Writes one line per pose, in order: the 12 numbers of the row-major 3x4
// matrix [R | t] of T_map_body (the body pose in the map / world frame),
//   r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2
// separated by single spaces, each in shortest round-trip text (reads back
// bit-exactly). No header, no comments and no times: the KITTI odometry
// convention keeps times in a separate file, so pose k belongs to the k-th
// time of the trajectory.tum written beside it (which carries the times).
// Atomic: "<file>.partial" is written and renamed into place. Throws
// InputError naming the file and the pose index, leaving no <file>, for a
// pose with a non-finite translation or a linear part that is not a rotation
// (|R^T R - I| > 1e-6 or det R < 0), or when the file cannot be written.
void WriteKittiTrajectory(const std::filesystem::path& file, const std::vector<StampedPose>& poses);

}  // namespace unimap::io
