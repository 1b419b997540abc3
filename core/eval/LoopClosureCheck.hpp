#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/StampedPose.hpp"

namespace unimap::eval {

// A motion a loop closure claims: the body at end_time_s seen from the body
// at start_time_s (for a closure against a submap: from the key scan that
// started the submap to the closing scan).
struct ClaimedMotion {
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  Eigen::Isometry3d T_start_end = Eigen::Isometry3d::Identity();
};

// One claim the truth calls false.
struct FalseClosure {
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  Eigen::Vector3d translation_error_m = Eigen::Vector3d::Zero();  // claim - truth, in the start body's frame
  double rotation_error_deg = 0.0;
};

// Claimed motions held against the ground truth.
struct LoopClosureCheck {
  std::size_t checked = 0;         // claims with truth at both times
  std::size_t false_closures = 0;  // off by more than a limit below
  double max_translation_error_m = 0.0;
  double max_rotation_error_deg = 0.0;
  double false_translation_m = 1.0;      // limit: a claim off by more is a false closure
  double false_rotation_deg = 5.0;       // limit: a claim turned by more is a false closure
  std::vector<FalseClosure> false_list;  // each false closure, in claim order
};

// Compares each claim with the truth's motion between its two times (truth
// sorted by time, interpolated; claims outside its span are not checked).
LoopClosureCheck CheckLoopClosures(const std::vector<ClaimedMotion>& claims, const std::vector<StampedPose>& truth);

}  // namespace unimap::eval
