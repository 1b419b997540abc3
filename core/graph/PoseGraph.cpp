#include "graph/PoseGraph.hpp"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <utility>

#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/types.h>
#include <Eigen/Cholesky>

#include "graph/RelativePoseCost.hpp"

namespace unimap::graph {
namespace {

bool IsFinite(const Eigen::Isometry3d& T) { return T.matrix().allFinite(); }

// Ceres settings from the graph options (silent: no glog output).
ceres::Solver::Options SolverOptions(const PoseGraphOptions& options) {
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver.max_num_iterations = options.max_iterations;
  solver.max_solver_time_in_seconds = options.max_solver_time_s;
  solver.num_threads = options.threads;
  solver.function_tolerance = options.function_tolerance;
  solver.gradient_tolerance = options.gradient_tolerance;
  solver.parameter_tolerance = options.parameter_tolerance;
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  std::string why;
  if (!solver.IsValid(&why)) {
    // Ceres built without a sparse library: the dense solver still works
    // (slowly) for small graphs.
    solver.linear_solver_type = ceres::DENSE_QR;
  }
  return solver;
}

}  // namespace

Matrix6d SqrtInformationFromCovariance(const Matrix6d& covariance) {
  if (!covariance.allFinite()) throw std::invalid_argument("SqrtInformationFromCovariance: non-finite covariance");
  const double scale = covariance.cwiseAbs().maxCoeff();
  if (!((covariance - covariance.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale)) {
    throw std::invalid_argument("SqrtInformationFromCovariance: covariance is not symmetric");
  }
  const Eigen::LLT<Matrix6d> covariance_llt(covariance);
  if (covariance_llt.info() != Eigen::Success) {
    throw std::invalid_argument("SqrtInformationFromCovariance: covariance is not positive definite");
  }
  Matrix6d information = covariance_llt.solve(Matrix6d::Identity());
  information = 0.5 * (information + information.transpose()).eval();
  // information = L L^T, so S = L^T is upper triangular with S^T S = information.
  const Eigen::LLT<Matrix6d> information_llt(information);
  if (information_llt.info() != Eigen::Success || !information.allFinite()) {
    throw std::invalid_argument("SqrtInformationFromCovariance: information is not positive definite");
  }
  return information_llt.matrixU();
}

PoseGraph::Node PoseGraph::MakeNode(const Eigen::Vector3d& p_world_node, const Eigen::Quaterniond& q_world_node) {
  Node node;
  node.p_world_node = p_world_node;
  node.q_world_node = q_world_node.normalized();
  node.T_world_node = Eigen::Isometry3d::Identity();
  node.T_world_node.linear() = node.q_world_node.toRotationMatrix();
  node.T_world_node.translation() = node.p_world_node;
  return node;
}

PoseGraph::Node PoseGraph::MakeNode(const Eigen::Isometry3d& T_world_node) {
  if (!IsFinite(T_world_node)) throw std::invalid_argument("PoseGraph: non-finite node pose");
  return MakeNode(T_world_node.translation(), Eigen::Quaterniond(T_world_node.linear()));
}

void PoseGraph::CheckNode(int node, const char* caller) const {
  if (node < 0 || static_cast<std::size_t>(node) >= nodes_.size()) {
    throw std::invalid_argument(std::string("PoseGraph::") + caller + ": unknown node id " + std::to_string(node));
  }
}

int PoseGraph::AddNode(const Eigen::Isometry3d& T_world_node) {
  nodes_.push_back(MakeNode(T_world_node));
  return static_cast<int>(nodes_.size() - 1);
}

void PoseGraph::AddConstraint(const PoseConstraint& constraint) {
  CheckNode(constraint.from_node, "AddConstraint");
  CheckNode(constraint.to_node, "AddConstraint");
  if (constraint.from_node == constraint.to_node) {
    throw std::invalid_argument("PoseGraph::AddConstraint: a constraint needs two different nodes");
  }
  if (!IsFinite(constraint.T_from_to) || !constraint.sqrt_information.allFinite()) {
    throw std::invalid_argument("PoseGraph::AddConstraint: non-finite measurement or sqrt_information");
  }
  constraints_.push_back(constraint);
}

const Eigen::Isometry3d& PoseGraph::Pose(int node) const {
  CheckNode(node, "Pose");
  return nodes_[static_cast<std::size_t>(node)].T_world_node;
}

void PoseGraph::SetPose(int node, const Eigen::Isometry3d& T_world_node) {
  CheckNode(node, "SetPose");
  nodes_[static_cast<std::size_t>(node)] = MakeNode(T_world_node);
}

std::size_t PoseGraph::NodeCount() const { return nodes_.size(); }

std::size_t PoseGraph::ConstraintCount() const { return constraints_.size(); }

const std::vector<PoseConstraint>& PoseGraph::constraints() const { return constraints_; }

OptimizationSummary PoseGraph::Optimize(const PoseGraphOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  OptimizationSummary out;
  out.nodes = nodes_.size();
  out.constraints = constraints_.size();
  std::string why;
  if (!options.IsValid(&why)) {
    out.reason = "invalid options: " + why;
    return out;
  }
  if (constraints_.empty()) {
    out.ok = true;
    out.reason = "no constraints: nothing to optimise";
    return out;
  }

  // Work on copies so a failed solve leaves the graph untouched.
  std::vector<Node> work = nodes_;
  ceres::Problem problem;  // owns cost functions, the loss and the manifold
  std::unique_ptr<ceres::LossFunction> loop_closure_loss;
  if (options.loop_closure_huber_scale > 0.0) {
    loop_closure_loss = std::make_unique<ceres::HuberLoss>(options.loop_closure_huber_scale);
  }
  ceres::Manifold* quaternion_manifold = new ceres::EigenQuaternionManifold;
  bool loss_used = false;
  for (const PoseConstraint& c : constraints_) {
    Node& a = work[static_cast<std::size_t>(c.from_node)];
    Node& b = work[static_cast<std::size_t>(c.to_node)];
    ceres::LossFunction* loss = c.kind == ConstraintKind::kLoopClosure ? loop_closure_loss.get() : nullptr;
    loss_used = loss_used || loss != nullptr;
    problem.AddResidualBlock(RelativePoseCost::Create(c.T_from_to, c.sqrt_information), loss, a.p_world_node.data(),
                             a.q_world_node.coeffs().data(), b.p_world_node.data(), b.q_world_node.coeffs().data());
    problem.SetManifold(a.q_world_node.coeffs().data(), quaternion_manifold);
    problem.SetManifold(b.q_world_node.coeffs().data(), quaternion_manifold);
  }
  // The Problem now owns the loss if it was used (and deletes it once).
  if (loss_used) static_cast<void>(loop_closure_loss.release());
  Node& anchor = work.front();
  if (problem.HasParameterBlock(anchor.p_world_node.data())) {
    problem.SetParameterBlockConstant(anchor.p_world_node.data());
    problem.SetParameterBlockConstant(anchor.q_world_node.coeffs().data());
  }

  ceres::Solver::Summary summary;
  ceres::Solve(SolverOptions(options), &problem, &summary);
  out.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.reason = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
  out.ok = summary.IsSolutionUsable();
  for (const Node& node : work) {
    out.ok = out.ok && node.p_world_node.allFinite() && node.q_world_node.coeffs().allFinite() &&
             node.q_world_node.norm() > 0.5;
  }
  if (out.ok) {
    // Only the variable nodes: the anchor and unconstrained nodes keep their
    // poses bit for bit.
    for (std::size_t i = 0; i < work.size(); ++i) {
      const Node& w = work[i];
      if (!problem.HasParameterBlock(w.p_world_node.data()) ||
          problem.IsParameterBlockConstant(w.p_world_node.data())) {
        continue;
      }
      nodes_[i] = MakeNode(w.p_world_node, w.q_world_node);
    }
  } else if (summary.IsSolutionUsable()) {
    out.reason = "non-finite solution (" + out.reason + ")";
  }
  out.solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace unimap::graph
