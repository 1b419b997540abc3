#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "graph/PoseGraphOptions.hpp"

namespace unimap::graph {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Where a constraint came from; loop closures (only) get the robust loss.
enum class ConstraintKind { kOdometry, kScanInSubmap, kLoopClosure };

// The measured pose of node `to` in the frame of node `from`.
struct PoseConstraint {
  int from_node = 0;                                            // id of node a
  int to_node = 0;                                              // id of node b
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();  // measured T_a_b
  // Square root S of the information (S^T S = Sigma^-1; upper triangular or
  // any full square root), order [translation xyz, rotation xyz]. The
  // whitened residual is S [p_ab - p_ab_meas ; 2 vec(q_ab_meas^-1 q_ab)]:
  // translation error in frame `from`, rotation error on the right (frame
  // `to`, q_ab = q_ab_meas Exp(dtheta)), equal to the rotation vector dtheta
  // for small errors (see RelativePoseCost).
  Matrix6d sqrt_information = Matrix6d::Identity();
  ConstraintKind kind = ConstraintKind::kOdometry;  // source of the measurement
};

// The square root of the information of a covariance in the same order as
// PoseConstraint::sqrt_information: the upper-triangular S with
// S^T S = covariance^-1 (the transposed Cholesky factor of the inverse).
// Throws std::invalid_argument when the covariance is not finite, not
// symmetric or not positive definite.
Matrix6d SqrtInformationFromCovariance(const Matrix6d& covariance);

// Outcome of PoseGraph::Optimize.
struct OptimizationSummary {
  bool ok = false;              // true: the solution was usable and the poses were updated
  std::string reason;           // Ceres termination ("CONVERGENCE: ...") or why it failed
  int iterations = 0;           // Levenberg-Marquardt steps taken (successful + rejected)
  double initial_cost = 0.0;    // 0.5 sum rho(|r|^2) of the whitened residuals, before
  double final_cost = 0.0;      // the same, after
  double solve_s = 0.0;         // wall time of building and solving the problem
  std::size_t nodes = 0;        // nodes in the graph
  std::size_t constraints = 0;  // constraints in the graph
};

// A sparse pose graph: a pose T_world_node per node and relative pose
// constraints between nodes, optimised with Ceres (after ceres
// examples/slam/pose_graph_3d). A copyable value type.
class PoseGraph {
 public:
  // Appends a node with the given initial pose and returns its id (0, 1, 2,
  // ... in order). Throws std::invalid_argument on non-finite values. The
  // rotation is re-normalised (stored as a unit quaternion).
  int AddNode(const Eigen::Isometry3d& T_world_node);

  // Appends a constraint. Throws std::invalid_argument when a node id is
  // unknown, from_node == to_node, or any value is not finite.
  void AddConstraint(const PoseConstraint& constraint);

  // The current pose of a node (std::invalid_argument on an unknown id); the
  // reference is valid until the next AddNode, SetPose or Optimize.
  const Eigen::Isometry3d& Pose(int node) const;
  // Overwrites the pose of a node (std::invalid_argument on an unknown id or
  // non-finite values).
  void SetPose(int node, const Eigen::Isometry3d& T_world_node);

  std::size_t NodeCount() const;                           // nodes added so far
  std::size_t ConstraintCount() const;                     // constraints added so far
  const std::vector<PoseConstraint>& constraints() const;  // in the order added

  // Minimises sum_c 0.5 rho_c(|r_c|^2) over the poses of the constrained
  // nodes (r_c: RelativePoseCost), with node 0 held constant, the Huber loss
  // (scale options.loop_closure_huber_scale) on loop closures only, and a
  // quaternion manifold on the rotations. On success (summary.ok) the poses
  // are updated; otherwise they are left unchanged and summary.reason says
  // why (invalid options, solver failure). Nodes in no constraint are not
  // touched; a component not connected to node 0 is free (gauge kept by the
  // solver's damping). A graph without constraints is a successful no-op.
  OptimizationSummary Optimize(const PoseGraphOptions& options);

 private:
  // One node: the Ceres parameters and the same pose as an isometry.
  struct Node {
    Eigen::Vector3d p_world_node = Eigen::Vector3d::Zero();            // position
    Eigen::Quaterniond q_world_node = Eigen::Quaterniond::Identity();  // unit rotation
    Eigen::Isometry3d T_world_node = Eigen::Isometry3d::Identity();    // from p and q
  };
  // A node from a finite pose (std::invalid_argument otherwise).
  static Node MakeNode(const Eigen::Isometry3d& T_world_node);
  // A node from a position and a (re-normalised) rotation.
  static Node MakeNode(const Eigen::Vector3d& p_world_node, const Eigen::Quaterniond& q_world_node);
  // Throws std::invalid_argument naming the caller when node is unknown.
  void CheckNode(int node, const char* caller) const;

  std::vector<Node> nodes_;
  std::vector<PoseConstraint> constraints_;
};

}  // namespace unimap::graph
