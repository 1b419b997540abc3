#include "io/KittiTrajectoryWriter.hpp"

#include <string>

#include "io/NumberText.hpp"
#include "io/PartialFile.hpp"
#include "io/TumLine.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Replaces *line by the KITTI row of T_map_body.
void KittiRow(const Eigen::Isometry3d& T_map_body, std::string* line) {
  line->clear();
  const Eigen::Matrix<double, 3, 4> rows = T_map_body.matrix().topRows<3>();
  for (Eigen::Index r = 0; r < 3; ++r) {
    for (Eigen::Index c = 0; c < 4; ++c) {
      AppendNumber(line, rows(r, c));
      line->push_back(r == 2 && c == 3 ? '\n' : ' ');
    }
  }
}

}  // namespace

void WriteKittiTrajectory(const std::filesystem::path& file, const std::vector<StampedPose>& poses) {
  // Checked before anything is created, so a rejected trajectory leaves no file.
  for (std::size_t k = 0; k < poses.size(); ++k) {
    // The time is not written, so only the pose is checked (time 0 is always valid).
    const std::string problem = TumPoseProblem(0.0, poses[k].T_map_body);
    if (!problem.empty()) throw InputError(file.string() + ": pose " + std::to_string(k) + ": " + problem);
  }
  WriteWholeFile(file, [&](PartialFile& out) {
    std::string line;
    for (const StampedPose& pose : poses) {
      KittiRow(pose.T_map_body, &line);
      out.Write(line);
    }
  });
}

}  // namespace unimap::io
