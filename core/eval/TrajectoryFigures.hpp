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

// Renders with cairo, in this order: trajectory_top.png (x-y) and
// trajectory_side.png (x-z), equal scales, 1000 wide and as high as the data
// needs (320 to 900), with the truth (drawn widest, underneath), the
// start-anchored and the ATE-aligned estimate; position_error.png (x, y, z
// panels) and rotation_error.png (roll, pitch, yaw panels), 1000 x 900 each,
// over time since the first associated pose, start-anchored.
std::vector<Figure> RenderTrajectoryFigures(const TrajectoryEvaluation& evaluation);

}  // namespace unimap::eval
