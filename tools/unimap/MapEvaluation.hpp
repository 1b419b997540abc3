#pragma once
// Map accuracy against a simulated world, shared by `unimap evaluate --map`
// and `unimap run` (definitions in docs/evaluation.md, section 4).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "World.hpp"
#include "eval/EvaluationReport.hpp"
#include "eval/MapError.hpp"
#include "eval/MetricRows.hpp"

namespace unimap::cli {

// The map error of one map file against one world.
struct MapEvaluation {
  std::filesystem::path map_file;    // the map evaluated (.pcd or .ply)
  std::filesystem::path world_file;  // the true world (a world.yaml primitives list)
  eval::MapErrorStats unaligned;     // points as stored: the map frame taken as the world frame
  // Points moved by T_world_map first (e.g. the trajectory's ATE alignment,
  // eval::TrajectoryErrors::alignment.T_target_source); empty when no
  // transform was given.
  std::optional<eval::MapErrorStats> aligned;
  // Points moved by the trajectory's start anchor (the first estimated pose
  // placed on the first true one, eval::TrajectoryErrors::T_true_est_anchor):
  // well defined also for short or straight trajectories, whose ATE
  // alignment leaves a rotation free; empty when no anchor was given.
  std::optional<eval::MapErrorStats> anchored;
};

// The map's points: .ply through io::ReadPlyVertices, .pcd through
// io::LoadPcdXyzi (extension case-insensitive). Throws InputError naming the
// file when it is missing, has another extension, or cannot be read.
std::vector<Eigen::Vector3f> LoadMapPoints(const std::filesystem::path& map_file);

// The world of a world.yaml (the primitives list `unimap simulate` writes
// into each dataset), built. Throws InputError when the file is missing and
// ConfigError (file, line, key, reason) when it is not a valid world.
sim::World LoadWorldFile(const std::filesystem::path& world_file);

// Which world file to use: world_option when not empty (InputError when it
// does not exist), else "world.yaml" beside truth_file when that exists,
// else none.
std::optional<std::filesystem::path> ResolveWorldFile(const std::string& world_option,
                                                      const std::filesystem::path& truth_file);

// Loads both files and computes the distance of every map point to the
// world's surfaces (sim::World::SurfaceDistance): unaligned always, aligned
// when T_world_map is given. Throws InputError (naming the map file) for a
// map that cannot be read, is empty or holds a non-finite point, for an
// empty world, and ConfigError for an invalid world file.
MapEvaluation EvaluateMapFile(const std::filesystem::path& map_file, const std::filesystem::path& world_file,
                              const std::optional<Eigen::Isometry3d>& T_world_map = std::nullopt,
                              const std::optional<Eigen::Isometry3d>& T_world_map_anchor = std::nullopt);

// The map metrics and files for eval::WriteEvaluationReport. Metrics in
// order: map_error_mean_m, map_error_p95_m, map_error_max_m, map_points,
// map_error_aligned_mean_m, map_error_aligned_p95_m, map_error_aligned_max_m,
// map_error_anchored_mean_m, map_error_anchored_p95_m, map_error_anchored_max_m
// (full precision in metrics.json, the aligned and anchored ones null when
// absent; rows with 4 decimals, "n/a" for an absent variant).
eval::ReportExtras MapReportExtras(const MapEvaluation& evaluation);

}  // namespace unimap::cli
