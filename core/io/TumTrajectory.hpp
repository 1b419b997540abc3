#pragma once
#include <cstdio>
#include <filesystem>
#include <vector>

#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Trajectories in the TUM format: "t x y z qx qy qz qw" per line, '#' comments.
// Reads every pose; throws InputError naming the file and line for a
// malformed line, a non-unit quaternion (|q| off by > 1e-3) or time going backwards.
std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& file);
// Writes atomically (temp file + rename), full double precision.
void WriteTumTrajectory(const std::filesystem::path& file, const std::vector<StampedPose>& poses);

// Appends poses as they come, for long runs; renamed into place by Close().
class TumTrajectoryWriter {
 public:
  explicit TumTrajectoryWriter(const std::filesystem::path& file);
  ~TumTrajectoryWriter();  // closes if still open
  TumTrajectoryWriter(const TumTrajectoryWriter&) = delete;
  TumTrajectoryWriter& operator=(const TumTrajectoryWriter&) = delete;
  void Write(const StampedPose& pose);
  void Close();

 private:
  std::filesystem::path file_;
  std::filesystem::path partial_;
  std::FILE* stream_ = nullptr;
};

}  // namespace unimap::io
