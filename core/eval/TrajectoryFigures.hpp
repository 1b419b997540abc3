#pragma once
// The evaluation's pictures (the paper's trajectory and error figures) as PNG bytes.
#include <string>
#include <vector>

#include "eval/TrajectoryEvaluation.hpp"

namespace unimap::eval {

// One rendered picture.
struct Figure {
  std::string file_name;  // e.g. "trajectory_top.png"
  std::string caption;    // one sentence for the report
  std::string png;        // PNG file bytes
};

// Renders, in this order: trajectory_top.png (x-y, equal scales, 1000 x 800)
// and trajectory_side.png (x-z, z stretched, 1000 x 500) with the truth, the start-anchored and the ATE-aligned estimate;
// position_error.png (x, y, z panels) and rotation_error.png (roll, pitch,
// yaw panels), 1000 x 990 each, over time since the first associated pose, start-anchored.
std::vector<Figure> RenderTrajectoryFigures(const TrajectoryEvaluation& evaluation);

}  // namespace unimap::eval
