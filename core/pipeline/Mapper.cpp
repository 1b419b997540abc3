#include "pipeline/Mapper.hpp"

#include <cmath>

#include "map/SurfacePoints.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "unimap/Errors.hpp"

namespace unimap::pipeline {
namespace {

constexpr std::size_t kMaxMessages = 50;

MapperOptions Checked(const MapperOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "", "mapper options: " + why);
  return options;
}

}  // namespace

Mapper::Mapper(const MapperOptions& options, std::shared_ptr<PayloadPlugin> plugin)
    : options_(Checked(options)),
      submaps_(std::make_shared<map::SubmapManager>(options_.submaps)),
      graph_(options_.scan_sigma_position_m, options_.scan_sigma_rotation_rad),
      finder_(options_.loop_search, options_.loop_closure, options_.submaps.map.resolution_m),
      optimizer_(options_.graph) {
  LocalizerOptions localizer_options = options_.localizer;
  localizer_options.localize_only = false;
  localizer_ = std::make_unique<Localizer>(localizer_options, std::move(plugin), submaps_,
                                           [this](KeyScan&& key) { OnKeyScan(std::move(key)); });
}

Mapper::~Mapper() = default;

void Mapper::Note(const std::string& message) {
  if (stats_.messages.size() < kMaxMessages) stats_.messages.push_back(message);
}

void Mapper::AddImu(const ImuSample& sample) {
  localizer_->AddImu(sample);
  PollOptimizer(false);
}

void Mapper::AddEncoder(const EncoderSample& sample) { localizer_->AddEncoder(sample); }

void Mapper::AddScan(io::ScanRecord scan) { localizer_->AddScan(std::move(scan)); }

void Mapper::AddOdometry(const OdometrySample& sample) { localizer_->AddOdometry(sample); }

void Mapper::Finish() {
  localizer_->Finish();
  PollOptimizer(true);
  if (any_closure_) {
    // The final trajectory and map come from a graph holding every constraint.
    optimizer_.Submit(graph_.graph());
    PollOptimizer(true);
  }
}

std::vector<ScanPose> Mapper::TakePoses() {
  std::vector<ScanPose> poses = localizer_->TakePoses();
  for (const ScanPose& p : poses) {
    local_poses_.push_back(
        {p.time_s, p.T_map_body.translation(), Eigen::Quaternionf(p.T_map_body.rotation().cast<float>())});
  }
  return poses;
}

void Mapper::OnKeyScan(KeyScan&& key) {
  const map::SubmapInsertion insertion = submaps_->last_insertion();
  const int k = graph_.AddKeyScan(key.time_s, key.T_local_body, insertion);
  for (std::size_t i = 0; i < insertion.created_ids.size(); ++i) {
    submap_starts_[insertion.created_ids[i]] = {key.time_s,
                                                key.T_local_body.inverse() * insertion.created_T_local_submaps[i]};
  }
  const Eigen::Vector3d position = key.T_local_body.translation();
  if (k > 0) path_m_ += (position - last_key_position_).norm();
  last_key_position_ = position;

  // The 3D scan in the body frame, kept for loop closure and the final map.
  const Eigen::Isometry3f T_body_local = key.T_local_body.inverse().cast<float>();
  std::vector<Eigen::Vector3f> points_body;
  points_body.reserve(key.points_local.size());
  for (const Eigen::Vector3f& p : key.points_local) points_body.push_back(T_body_local * p);

  for (map::RetiredSubmap& retired : submaps_->TakeRetired()) finder_.AddRetired(std::move(retired), path_m_);

  if (options_.loop_search.enabled && k % options_.loop_search.every_3d_scans == 0) {
    StageTimer timer(&stats_.loop_search_s);
    const Eigen::Isometry3d T_world_body = graph_.T_world_local() * key.T_local_body;
    for (const LoopClosure& closure : finder_.Search(k, points_body, T_world_body, path_m_, graph_)) {
      graph_.AddLoopClosure(closure);
      closures_.push_back({key.time_s, k, closure.submap_id, closure.T_submap_body});
      if (!any_closure_) stats_.first_loop_closure_time_s = key.time_s;
      any_closure_ = true;
    }
    for (const std::string& m : finder_.TakeMessages()) Note(m);
  }
  // The final map keeps from each key scan only the voxels (local frame, map
  // resolution) no earlier key scan holds: a slow or hovering sensor sees the
  // same voxels again and again, and keeping them all made memory grow with
  // time instead of with the area mapped (docs/reliability.md, memory over
  // long runs). A place revisited after drift lies in other local voxels and
  // is kept again.
  const double voxel_m = options_.submaps.map.resolution_m;
  std::vector<Eigen::Vector3f> kept;
  std::vector<float> kept_intensities;
  const bool intensities = key.intensities.size() == key.points_local.size();
  for (std::size_t i = 0; i < key.points_local.size(); ++i) {
    const Eigen::Vector3f& p = key.points_local[i];
    const Eigen::Vector3i cell((p / static_cast<float>(voxel_m)).array().floor().cast<int>());
    if (held_voxels_.Insert(cell)) {
      kept.push_back(points_body[i]);
      if (intensities) kept_intensities.push_back(key.intensities[i]);
    }
  }
  stats_.key_scan_points += points_body.size();
  stats_.map_points_kept += kept.size();
  kept.shrink_to_fit();  // held for the whole run: no spare capacity (an hour holds thousands)
  kept_intensities.shrink_to_fit();
  key_points_body_.push_back(std::move(kept));
  key_intensities_.push_back(std::move(kept_intensities));

  // Every I 3D scans (once a loop closure exists: without one the graph,
  // built from a single trajectory, is already at its optimum).
  if (any_closure_ && (k + 1) % options_.scans_3d_per_optimization == 0) SubmitOptimization();
}

void Mapper::SubmitOptimization() {
  PollOptimizer(false);
  optimizer_.Submit(graph_.graph());  // busy: the next submission carries these constraints
  if (options_.wait_for_background) PollOptimizer(true);
}

void Mapper::PollOptimizer(bool wait) {
  if (wait) optimizer_.Wait();
  std::optional<graph::OptimizedPoses> result = optimizer_.TakeResult();
  if (!result) return;
  stats_.optimization_s += result->summary.solve_s;
  if (!result->summary.ok) {
    ++stats_.optimization_failures;
    Note("optimisation failed: " + result->summary.reason);
    return;
  }
  ++stats_.optimizations;
  graph_.ApplyOptimized(result->T_world_node);
}

std::vector<StampedPose> Mapper::OptimizedTrajectory() const {
  std::vector<StampedPose> out;
  out.reserve(local_poses_.size());
  for (const LocalPose& p : local_poses_) {
    Eigen::Isometry3d T_local_body = Eigen::Isometry3d::Identity();
    T_local_body.linear() = p.q_local_body.cast<double>().normalized().toRotationMatrix();
    T_local_body.translation() = p.p_local_body;
    out.push_back({p.time_s, graph_.ToWorld(p.time_s, T_local_body)});
  }
  return out;
}

std::vector<Eigen::Vector3f> Mapper::MapPoints(double voxel_m, std::vector<float>* intensities) const {
  // The first point of each voxel_m cell in key-scan order (what
  // matching::VoxelDownsample of every key scan's points gives) without
  // gathering all of them first. Intensities only when every kept point has one.
  bool all_intensities = intensities != nullptr;
  for (std::size_t k = 0; all_intensities && k < key_points_body_.size(); ++k) {
    all_intensities = key_intensities_[k].size() == key_points_body_[k].size();
  }
  if (intensities != nullptr) intensities->clear();
  std::vector<Eigen::Vector3f> points;
  matching::VoxelKeySet seen;
  const double inv_voxel = voxel_m > 0.0 ? 1.0 / voxel_m : 0.0;
  for (std::size_t k = 0; k < key_points_body_.size(); ++k) {
    const Eigen::Isometry3f T_world_body = graph_.T_world_key(static_cast<int>(k)).cast<float>();
    for (std::size_t i = 0; i < key_points_body_[k].size(); ++i) {
      const Eigen::Vector3f p = T_world_body * key_points_body_[k][i];
      if (voxel_m > 0.0 && !seen.insert(matching::VoxelKey(p, inv_voxel)).second) continue;
      points.push_back(p);
      if (all_intensities) intensities->push_back(key_intensities_[k][i]);
    }
  }
  return points;
}

StageTimes Mapper::Times() const {
  StageTimes times = localizer_->Times();
  times.loop_search_s = stats_.loop_search_s;
  times.optimization_s = stats_.optimization_s;
  return times;
}

std::vector<LoopClosureLink> Mapper::LoopClosureLinks() const {
  std::vector<LoopClosureLink> links;
  for (const AcceptedClosure& c : closures_) {
    Eigen::Isometry3d T_world_submap = Eigen::Isometry3d::Identity();
    if (!graph_.T_world_submap(c.submap_id, &T_world_submap)) continue;
    LoopClosureLink link{c.time_s, graph_.T_world_key(c.key_scan).translation(), T_world_submap.translation()};
    const auto start = submap_starts_.find(c.submap_id);
    if (start != submap_starts_.end()) {
      link.submap_start_time_s = start->second.time_s;
      link.T_start_body = start->second.T_body_submap * c.T_submap_body;
    }
    links.push_back(link);
  }
  return links;
}

MapperStats Mapper::stats() const {
  MapperStats s = stats_;
  s.key_scans = graph_.key_scan_count();
  s.submaps = submaps_->started_count();
  s.retired_submaps = finder_.retired_count();
  s.retired_points = finder_.retired_points();
  s.retired_bytes = finder_.retired_bytes();
  s.loop_closures = graph_.loop_closures();
  s.loop_search = finder_.stats();
  return s;
}

}  // namespace unimap::pipeline
