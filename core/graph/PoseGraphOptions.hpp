#pragma once
#include <string>

#include "options/FieldVisitor.hpp"

namespace unimap::graph {

// Settings of one sparse pose graph optimisation (Ceres Levenberg-Marquardt,
// sparse normal Cholesky).
struct PoseGraphOptions {
  int max_iterations = 20;  // Levenberg-Marquardt iterations at most
  double loop_closure_huber_scale =
      1.0;          // Huber threshold on the whitened loop-closure residual norm; <= 0: plain least squares
  int threads = 1;  // Ceres threads (Jacobian evaluation, linear solve)
  double max_solver_time_s = 5.0;     // wall-time limit of the solve
  double function_tolerance = 1e-6;   // stop when |delta cost| / cost < this
  double gradient_tolerance = 1e-10;  // stop when the max-norm of the projected gradient < this
  double parameter_tolerance = 1e-8;  // stop when |delta x| / (|x| + tol) < this

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  // True when every field is in range; otherwise false with the reason in
  // *why (when why is not null).
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::graph
