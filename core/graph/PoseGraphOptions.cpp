#include "graph/PoseGraphOptions.hpp"

#include <cmath>

namespace unimap::graph {

bool PoseGraphOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  if (max_iterations < 1 || threads < 1) {
    *why = "max_iterations and threads must be at least 1";
    return false;
  }
  if (!std::isfinite(loop_closure_huber_scale)) {
    *why = "loop_closure_huber_scale must be finite (<= 0 disables the robust loss)";
    return false;
  }
  if (!(max_solver_time_s > 0.0) || !std::isfinite(max_solver_time_s)) {
    *why = "max_solver_time_s must be positive and finite";
    return false;
  }
  if (!(function_tolerance >= 0.0) || !(gradient_tolerance >= 0.0) || !(parameter_tolerance >= 0.0) ||
      !std::isfinite(function_tolerance) || !std::isfinite(gradient_tolerance) || !std::isfinite(parameter_tolerance)) {
    *why = "function_tolerance, gradient_tolerance and parameter_tolerance must be finite and >= 0";
    return false;
  }
  return true;
}

void PoseGraphOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("max_iterations", &max_iterations, "count");
  v.Field("loop_closure_huber_scale", &loop_closure_huber_scale, "");
  v.Field("threads", &threads, "count");
  v.Field("max_solver_time_s", &max_solver_time_s, "s");
  v.Field("function_tolerance", &function_tolerance, "");
  v.Field("gradient_tolerance", &gradient_tolerance, "");
  v.Field("parameter_tolerance", &parameter_tolerance, "");
}

}  // namespace unimap::graph
