#pragma once
#include <string>

namespace unimap::cli {

// `unimap bench --matrix` (issue 19): every scenario with every payload the
// scenarios use (each with its own shipped platform file), and every
// scenario with its default payload at twice the speed and yaw rate and with
// 2.5x the IMU white noise and twice its biases. Each case is simulated and
// mapped by this executable in child processes (`simulate`, then `run`), each
// pinned to one core; the table replaces the generated part of the report
// (between the markers kBegin and kEnd), the text around it is kept.
struct MatrixOptions {
  std::string configs = "configs";         // folder with scenarios/ and platforms/
  std::string out = "docs/robustness.md";  // report whose generated table is (re)written
  std::string work_dir;                    // datasets and run folders kept (and reused) here; empty: temporary
  double max_duration_s = 0.0;             // > 0: simulate and map only the first seconds of each case
  int jobs = 1;                            // cases at once, each on its own core
  unsigned seed = 0;                       // simulation seed of every case (0: each scenario's own)
  std::string only;                        // run only cases whose name contains this text
};

// Runs the matrix and rewrites options.out; 0 when every case met its
// targets, 1 otherwise (the report says which and why).
int RunRobustnessMatrix(const MatrixOptions& options);

}  // namespace unimap::cli
