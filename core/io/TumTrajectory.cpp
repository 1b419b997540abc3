#include "io/TumTrajectory.hpp"

#include "io/DatasetLayout.hpp"
#include "io/NumberLineStream.hpp"
#include "io/NumberText.hpp"
#include "io/PartialFile.hpp"
#include "io/TumLine.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Replaces *line by the TUM row of `pose`; throws InputError naming `file`
// for a pose that cannot be written or a time before *last_time_s.
void AppendCheckedRow(const std::filesystem::path& file, const StampedPose& pose, double* last_time_s, bool* has_last,
                      std::string* line) {
  const std::string problem = TumPoseProblem(pose.time_s, pose.T_map_body);
  if (!problem.empty()) throw InputError(file.string() + ": " + problem);
  if (*has_last && pose.time_s < *last_time_s) {
    std::string text;
    AppendNumber(&text, pose.time_s);
    text += " s after ";
    AppendNumber(&text, *last_time_s);
    throw InputError(file.string() + ": time goes backwards: " + text + " s");
  }
  line->clear();
  AppendTumRow(line, pose.time_s, pose.T_map_body);
  *last_time_s = pose.time_s;
  *has_last = true;
}

}  // namespace

std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& file) {
  NumberLineStream rows(file, kTumColumns);
  std::vector<StampedPose> poses;
  double values[kTumColumns];
  while (rows.Next(values)) {
    StampedPose pose;
    pose.time_s = values[0];
    pose.T_map_body = TumRowPose(values, rows);
    poses.push_back(pose);
  }
  return poses;
}

void WriteTumTrajectory(const std::filesystem::path& file, const std::vector<StampedPose>& poses) {
  WriteWholeFile(file, [&](PartialFile& partial) {
    partial.Write(layout::kPoseHeader);
    std::string line;
    double last_time_s = 0.0;
    bool has_last = false;
    for (const StampedPose& pose : poses) {
      AppendCheckedRow(file, pose, &last_time_s, &has_last, &line);
      partial.Write(line);
    }
  });
}

TumTrajectoryWriter::TumTrajectoryWriter(const std::filesystem::path& file)
    : file_(file), partial_(std::make_unique<PartialFile>(file)) {
  partial_->Write(layout::kPoseHeader);
}

TumTrajectoryWriter::~TumTrajectoryWriter() {
  if (!partial_) return;
  try {
    Close();
  } catch (const std::exception&) {
    // Destructors must not throw; PartialFile's destructor removes the ".partial".
  }
}

void TumTrajectoryWriter::Write(const StampedPose& pose) {
  if (!partial_) throw InputError(file_.string() + ": write after Close()");
  AppendCheckedRow(file_, pose, &last_time_s_, &has_last_, &line_);
  partial_->Write(line_);
}

void TumTrajectoryWriter::Close() {
  if (!partial_) throw InputError(file_.string() + ": closed twice");
  const std::unique_ptr<PartialFile> partial = std::move(partial_);
  partial->Commit();
}

}  // namespace unimap::io
