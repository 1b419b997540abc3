#pragma once
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "graph/BackgroundOptimizer.hpp"
#include "graph/PoseGraph.hpp"
#include "map/SubmapManager.hpp"

namespace unimap::pipeline {

// A loop closure: a 3D scan matched against an older (retired) submap.
struct LoopClosure {
  int key_scan = 0;                                                                  // TrajectoryGraph key-scan index
  int submap_id = 0;                                                                 // SubmapManager id
  Eigen::Isometry3d T_submap_body = Eigen::Isometry3d::Identity();                   // measured
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity();  // [dp, dtheta]
};

// The sparse pose graph of a mapping run (docs/design.md 1.5): a node per submap
// and per 3D scan ("key scan"), in the local odometry frame the localiser
// works in. Constraints: each key scan in every submap it was inserted into
// (from localisation), consecutive key scans that share no submap
// (odometry), and loop closures.
// Node 0 (the first submap) is fixed, so the world frame is the local frame
// at the start. Optimised poses give T_world_local, the correction of the
// live estimate, and the world pose of every key scan.
class TrajectoryGraph {
 public:
  // Sigmas of scan-in-submap and odometry constraints.
  TrajectoryGraph(double sigma_position_m, double sigma_rotation_rad);

  // Adds nodes for the submaps an insertion created and a node for the key
  // scan with its constraints; returns the key-scan index (0, 1, ...).
  int AddKeyScan(double time_s, const Eigen::Isometry3d& T_local_body, const map::SubmapInsertion& insertion);
  // Adds a loop-closure constraint (robust loss in the optimiser).
  void AddLoopClosure(const LoopClosure& closure);
  // Takes an optimisation result for the graph as submitted (nodes added
  // since keep their local poses, moved by the newest correction).
  void ApplyOptimized(const std::vector<Eigen::Isometry3d>& T_world_node);

  const graph::PoseGraph& graph() const { return graph_; }
  std::size_t key_scan_count() const { return key_scans_.size(); }
  // The key scan's body pose in the world (optimised).
  Eigen::Isometry3d T_world_key(int key_scan) const;
  // A submap's optimised frame; false when the id has no node.
  bool T_world_submap(int submap_id, Eigen::Isometry3d* T_world_submap) const;
  // Correction of the newest part of the trajectory: T_world_local.
  const Eigen::Isometry3d& T_world_local() const { return T_world_local_; }
  // World pose of a local body pose at time t: corrected by the key scan
  // whose accumulation holds t (the first ending at or after t; after the
  // last key scan, the last one).
  Eigen::Isometry3d ToWorld(double time_s, const Eigen::Isometry3d& T_local_body) const;
  std::size_t loop_closures() const { return loop_closures_; }

 private:
  struct KeyScanNode {
    double time_s;
    int node;
    Eigen::Isometry3d T_local_body;
  };
  int SubmapNode(int submap_id) const;

  graph::PoseGraph graph_;
  Eigen::Matrix<double, 6, 6> sqrt_information_;
  std::vector<KeyScanNode> key_scans_;
  std::map<int, int> submap_nodes_;              // submap id -> node
  std::vector<Eigen::Isometry3d> T_local_node_;  // as first added, per node
  std::vector<int> previous_submap_ids_;         // the submaps the last key scan went into
  Eigen::Isometry3d T_world_local_ = Eigen::Isometry3d::Identity();
  std::size_t loop_closures_ = 0;
};

}  // namespace unimap::pipeline
