#pragma once
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "graph/BackgroundOptimizer.hpp"
#include "map/SubmapManager.hpp"
#include "matching/VoxelBlockSet.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "pipeline/EventSink.hpp"
#include "pipeline/Localizer.hpp"
#include "pipeline/LoopClosureFinder.hpp"
#include "pipeline/MapperOptions.hpp"
#include "pipeline/TrajectoryGraph.hpp"
#include "unimap/PayloadPlugin.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::pipeline {

// What the mapping back end did.
struct MapperStats {
  std::size_t key_scans = 0;                // 3D scans (pose-graph scan nodes)
  int submaps = 0;                          // submaps started
  std::size_t retired_submaps = 0;          // retired submaps kept for loop closure (not the redundant)
  std::size_t retired_points = 0;           // surface points they keep
  std::size_t retired_bytes = 0;            // bytes those points take
  std::size_t loop_closures = 0;            // accepted loop-closure constraints
  std::size_t optimizations = 0;            // pose-graph optimisations finished and applied
  std::size_t optimization_failures = 0;    // optimisations that reported !ok (result ignored)
  double optimization_s = 0.0;              // total solver time
  double loop_search_s = 0.0;               // total time searching and matching loop closures
  double first_loop_closure_time_s = -1.0;  // time of the 3D scan of the first accepted closure (-1: none)
  LoopSearchStats loop_search;              // candidate counts
  std::size_t key_scan_points = 0;          // points of all key scans (one per map voxel each)
  std::size_t map_points_kept = 0;          // of those, kept for MapPoints: each local-frame voxel once
  std::vector<std::string> messages;        // loop closures and optimisation notes (first few)
};

// An accepted loop closure, for drawing: where the closing 3D scan was and
// the origin of the older submap it matched (world frame, optimised poses);
// and, for checking it against ground truth, the motion it claims between
// the body when the submap was started and the closing scan.
struct LoopClosureLink {
  double time_s = 0.0;                                     // the closing 3D scan's time
  Eigen::Vector3d scan_world = Eigen::Vector3d::Zero();    // its body position
  Eigen::Vector3d submap_world = Eigen::Vector3d::Zero();  // the matched submap's origin
  double submap_start_time_s = 0.0;                        // time of the key scan that started the submap
  // Measured: T_start_body = T_start_submap (odometry when the submap was
  // started) * T_submap_body (the loop-closure match).
  Eigen::Isometry3d T_start_body = Eigen::Isometry3d::Identity();
};

// The paper's full system (docs/design.md 1): wires the Localizer (plugin ->
// deskew -> GPF -> ESKF), the SubmapManager it matches against and inserts
// into, the TrajectoryGraph (a node per 3D scan and per submap), the
// LoopClosureFinder and the background pose-graph optimiser. The localiser
// works in its local odometry frame; optimisation only changes the
// correction T_world_local and the final trajectory and map.
class Mapper : public EventSink {
 public:
  // Throws ConfigError when the options are invalid.
  Mapper(const MapperOptions& options, std::shared_ptr<PayloadPlugin> plugin);
  ~Mapper() override;

  void AddImu(const ImuSample& sample) override;
  void AddEncoder(const EncoderSample& sample) override;
  void AddScan(io::ScanRecord scan) override;
  void AddOdometry(const OdometrySample& sample) override;
  // Processes the remaining scans and runs a final optimisation.
  void Finish() override;
  // Localised poses (local odometry frame, as the filter estimated them) since the last call.
  std::vector<ScanPose> TakePoses() override;
  std::size_t ScansReceived() const override { return localizer_->ScansReceived(); }

  // Every scan pose so far in the world frame, corrected by the optimised
  // pose graph (after Finish: the final trajectory).
  std::vector<StampedPose> OptimizedTrajectory() const;
  // Every key scan's points in the world frame (optimised poses), one per
  // voxel_m voxel; with intensities, theirs (one per point when the input
  // had them, else left empty).
  std::vector<Eigen::Vector3f> MapPoints(double voxel_m, std::vector<float>* intensities = nullptr) const;
  const Eigen::Isometry3d& T_world_local() const { return graph_.T_world_local(); }
  const LocalizerStats& localizer_stats() const { return localizer_->stats(); }
  // Where the time went: the localiser's and its map's stages, loop search, optimisation.
  StageTimes Times() const;
  MapperStats stats() const;
  // Every accepted loop closure, in acceptance order.
  std::vector<LoopClosureLink> LoopClosureLinks() const;

 private:
  void OnKeyScan(KeyScan&& key);
  void SubmitOptimization();
  void PollOptimizer(bool wait);
  void Note(const std::string& message);

  MapperOptions options_;
  std::shared_ptr<map::SubmapManager> submaps_;
  TrajectoryGraph graph_;
  LoopClosureFinder finder_;
  graph::BackgroundOptimizer optimizer_;
  // Every scan's pose so far (local frame), kept compact: a long run holds
  // one per line scan (144,235 in an hour of the tunnel), so no diagnostics,
  // 48 bytes each, and a deque so that growing never copies them all.
  struct LocalPose {
    double time_s = 0.0;
    Eigen::Vector3d p_local_body = Eigen::Vector3d::Zero();            // position, exact
    Eigen::Quaternionf q_local_body = Eigen::Quaternionf::Identity();  // rotation, to about 1e-7 rad
  };
  std::deque<LocalPose> local_poses_;
  std::vector<std::vector<Eigen::Vector3f>> key_points_body_;  // per key scan, its new voxels only
  std::vector<std::vector<float>> key_intensities_;            // their intensities (empty: none in the input)
  matching::VoxelBlockSet held_voxels_;                        // voxels (local frame) key_points_body_ holds
  double path_m_ = 0.0;                                        // distance travelled by the key scans
  Eigen::Vector3d last_key_position_ = Eigen::Vector3d::Zero();
  bool any_closure_ = false;
  struct AcceptedClosure {
    double time_s;
    int key_scan;
    int submap_id;
    Eigen::Isometry3d T_submap_body;  // measured
  };
  struct SubmapStart {
    double time_s;                    // key scan that started the submap
    Eigen::Isometry3d T_body_submap;  // the submap's frame seen from that key scan's body
  };
  std::map<int, SubmapStart> submap_starts_;  // by submap id
  std::vector<AcceptedClosure> closures_;     // for LoopClosureLinks
  MapperStats stats_;
  std::unique_ptr<Localizer> localizer_;  // last: its callback uses the members above
};

}  // namespace unimap::pipeline
