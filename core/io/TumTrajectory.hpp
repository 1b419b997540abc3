#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "unimap/StampedPose.hpp"

namespace unimap::io {

class PartialFile;

// Trajectories in the TUM format: "t x y z qx qy qz qw" per line (the
// quaternion rotates body into map, Hamilton, scalar last), '#' comments and
// blank lines skipped, fields separated by spaces or tabs.
// Reads every pose (quaternion normalised); throws InputError naming the file
// and line for a malformed line, a non-finite value, a non-unit quaternion
// (|q| off by > 1e-3) or time going backwards.
std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& file);
// Writes atomically ("<file>.partial" + rename), every number in shortest
// round-trip text (times and positions read back bit-exactly). Throws
// InputError, leaving no <file>, for a pose TumTrajectoryWriter::Write rejects.
void WriteTumTrajectory(const std::filesystem::path& file, const std::vector<StampedPose>& poses);

// Appends poses as they come, for long runs, to "<file>.partial"; renamed
// into place by Close().
class TumTrajectoryWriter {
 public:
  // Creates "<file>.partial"; throws InputError if it cannot.
  explicit TumTrajectoryWriter(const std::filesystem::path& file);
  // Closes (renames into place) if still open, swallowing errors: a run that
  // stops early keeps the poses it wrote. Call Close() to see errors.
  ~TumTrajectoryWriter();
  TumTrajectoryWriter(const TumTrajectoryWriter&) = delete;
  TumTrajectoryWriter& operator=(const TumTrajectoryWriter&) = delete;
  // Appends one pose; throws InputError for a non-finite time or pose, a
  // linear part that is not a rotation, time before the previous pose's, or
  // a write after Close().
  void Write(const StampedPose& pose);
  // Flushes and renames "<file>.partial" to <file>; throws InputError on
  // failure or when already closed.
  void Close();

 private:
  std::filesystem::path file_;            // final name
  std::unique_ptr<PartialFile> partial_;  // open until Close()
  std::string line_;                      // reused text of one row
  double last_time_s_ = 0.0;              // time of the previous pose
  bool has_last_ = false;                 // a pose was written
};

}  // namespace unimap::io
