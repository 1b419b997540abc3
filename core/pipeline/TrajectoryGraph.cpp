#include "pipeline/TrajectoryGraph.hpp"

#include <algorithm>
#include <stdexcept>

namespace unimap::pipeline {

TrajectoryGraph::TrajectoryGraph(double sigma_position_m, double sigma_rotation_rad) {
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  covariance.diagonal() << Eigen::Vector3d::Constant(sigma_position_m * sigma_position_m),
      Eigen::Vector3d::Constant(sigma_rotation_rad * sigma_rotation_rad);
  sqrt_information_ = graph::SqrtInformationFromCovariance(covariance);
}

int TrajectoryGraph::SubmapNode(int submap_id) const {
  const auto it = submap_nodes_.find(submap_id);
  return it == submap_nodes_.end() ? -1 : it->second;
}

int TrajectoryGraph::AddKeyScan(double time_s, const Eigen::Isometry3d& T_local_body,
                                const map::SubmapInsertion& insertion) {
  // New submaps get a node at their local frame, moved by the current
  // correction so the optimised world stays continuous.
  for (std::size_t i = 0; i < insertion.created_ids.size(); ++i) {
    const Eigen::Isometry3d& T_local_submap = insertion.created_T_local_submaps[i];
    submap_nodes_[insertion.created_ids[i]] = graph_.AddNode(T_world_local_ * T_local_submap);
    T_local_node_.push_back(T_local_submap);
  }
  const int node = graph_.AddNode(T_world_local_ * T_local_body);
  T_local_node_.push_back(T_local_body);
  // Scan in submap (localisation): the key scan's pose in each receiving submap.
  for (std::size_t i = 0; i < insertion.submap_ids.size(); ++i) {
    const int submap_node = SubmapNode(insertion.submap_ids[i]);
    if (submap_node < 0) throw std::logic_error("TrajectoryGraph: key scan inserted into an unknown submap");
    graph::PoseConstraint c;
    c.from_node = submap_node;
    c.to_node = node;
    c.T_from_to = insertion.T_local_submaps[i].inverse() * T_local_body;
    c.sqrt_information = sqrt_information_;
    c.kind = graph::ConstraintKind::kScanInSubmap;
    graph_.AddConstraint(c);
  }
  // Odometry between consecutive key scans, only when they share no submap:
  // otherwise their scan-in-submap constraints already hold the same
  // relative pose (all three come from the same local-frame poses), and a
  // third constraint per key scan would count it twice and make the solve
  // half as large again (docs/reliability.md, memory over long runs).
  bool share_submap = false;
  for (const int id : insertion.submap_ids) {
    share_submap = share_submap || std::find(previous_submap_ids_.begin(), previous_submap_ids_.end(), id) !=
                                       previous_submap_ids_.end();
  }
  previous_submap_ids_ = insertion.submap_ids;
  if (!key_scans_.empty() && !share_submap) {
    const KeyScanNode& previous = key_scans_.back();
    graph::PoseConstraint c;
    c.from_node = previous.node;
    c.to_node = node;
    c.T_from_to = previous.T_local_body.inverse() * T_local_body;
    c.sqrt_information = sqrt_information_;
    c.kind = graph::ConstraintKind::kOdometry;
    graph_.AddConstraint(c);
  }
  key_scans_.push_back({time_s, node, T_local_body});
  return static_cast<int>(key_scans_.size()) - 1;
}

void TrajectoryGraph::AddLoopClosure(const LoopClosure& closure) {
  const int submap_node = SubmapNode(closure.submap_id);
  if (submap_node < 0 || closure.key_scan < 0 || closure.key_scan >= static_cast<int>(key_scans_.size())) {
    throw std::logic_error("TrajectoryGraph: loop closure between unknown nodes");
  }
  graph::PoseConstraint c;
  c.from_node = submap_node;
  c.to_node = key_scans_[static_cast<std::size_t>(closure.key_scan)].node;
  c.T_from_to = closure.T_submap_body;
  c.sqrt_information = graph::SqrtInformationFromCovariance(closure.covariance);
  c.kind = graph::ConstraintKind::kLoopClosure;
  graph_.AddConstraint(c);
  ++loop_closures_;
}

void TrajectoryGraph::ApplyOptimized(const std::vector<Eigen::Isometry3d>& T_world_node) {
  const std::size_t n = std::min(T_world_node.size(), graph_.NodeCount());
  if (n == 0) return;
  for (std::size_t i = 0; i < n; ++i) graph_.SetPose(static_cast<int>(i), T_world_node[i]);
  // The newest optimised key scan defines the correction of everything after it.
  int newest = -1;
  for (auto it = key_scans_.rbegin(); it != key_scans_.rend(); ++it) {
    if (static_cast<std::size_t>(it->node) < n) {
      newest = it->node;
      break;
    }
  }
  if (newest < 0) return;
  T_world_local_ =
      T_world_node[static_cast<std::size_t>(newest)] * T_local_node_[static_cast<std::size_t>(newest)].inverse();
  for (std::size_t i = n; i < graph_.NodeCount(); ++i) {
    graph_.SetPose(static_cast<int>(i), T_world_local_ * T_local_node_[i]);
  }
}

Eigen::Isometry3d TrajectoryGraph::T_world_key(int key_scan) const {
  return graph_.Pose(key_scans_.at(static_cast<std::size_t>(key_scan)).node);
}

bool TrajectoryGraph::T_world_submap(int submap_id, Eigen::Isometry3d* T_world_submap) const {
  const int node = SubmapNode(submap_id);
  if (node < 0) return false;
  *T_world_submap = graph_.Pose(node);
  return true;
}

Eigen::Isometry3d TrajectoryGraph::ToWorld(double time_s, const Eigen::Isometry3d& T_local_body) const {
  if (key_scans_.empty()) return T_world_local_ * T_local_body;
  auto it = std::lower_bound(key_scans_.begin(), key_scans_.end(), time_s,
                             [](const KeyScanNode& k, double t) { return k.time_s < t; });
  if (it == key_scans_.end()) --it;
  // Eq.: T_world_body = T_world_key * T_local_key^-1 * T_local_body.
  return graph_.Pose(it->node) * it->T_local_body.inverse() * T_local_body;
}

}  // namespace unimap::pipeline
