#include "MapEvaluation.hpp"

#include <algorithm>
#include <cctype>

#include <yaml-cpp/yaml.h>

#include "TextFormat.hpp"
#include "WorldLoader.hpp"
#include "eval/MetricsJson.hpp"
#include "io/PcdPointLoader.hpp"
#include "io/PlyReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

std::string Lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Every map metric: its full-precision JSON value and its (key, display value, meaning) row.
std::vector<eval::ExtraMetric> Metrics(const MapEvaluation& e) {
  const eval::MapErrorStats& u = e.unaligned;
  const auto value = [](const std::optional<eval::MapErrorStats>& stats, double eval::MapErrorStats::*field) {
    return stats ? nlohmann::ordered_json((*stats).*field) : nlohmann::ordered_json(nullptr);
  };
  const auto shown = [](const std::optional<eval::MapErrorStats>& stats, double eval::MapErrorStats::*field) {
    return stats ? Fixed((*stats).*field, 4) : std::string("n/a");
  };
  const auto aligned = [&](double eval::MapErrorStats::*field) { return value(e.aligned, field); };
  const auto aligned_shown = [&](double eval::MapErrorStats::*field) { return shown(e.aligned, field); };
  const auto anchored = [&](double eval::MapErrorStats::*field) { return value(e.anchored, field); };
  const auto anchored_shown = [&](double eval::MapErrorStats::*field) { return shown(e.anchored, field); };
  using S = eval::MapErrorStats;
  return {
      {u.mean_m,
       {"map_error_mean_m", Fixed(u.mean_m, 4),
        "mean distance of the map points to the true surfaces (no alignment), m"}},
      {u.p95_m, {"map_error_p95_m", Fixed(u.p95_m, 4), "95th percentile (nearest rank) of that distance, m"}},
      {u.max_m, {"map_error_max_m", Fixed(u.max_m, 4), "largest distance of a map point, m"}},
      {u.points, {"map_points", std::to_string(u.points), "map points evaluated"}},
      {aligned(&S::mean_m),
       {"map_error_aligned_mean_m", aligned_shown(&S::mean_m),
        "mean distance after moving the map by the ATE alignment, m"}},
      {aligned(&S::p95_m),
       {"map_error_aligned_p95_m", aligned_shown(&S::p95_m), "95th percentile after the ATE alignment, m"}},
      {aligned(&S::max_m),
       {"map_error_aligned_max_m", aligned_shown(&S::max_m), "largest distance after the ATE alignment, m"}},
      {anchored(&S::mean_m),
       {"map_error_anchored_mean_m", anchored_shown(&S::mean_m),
        "mean distance after moving the map by the start anchor (first poses made to coincide), m"}},
      {anchored(&S::p95_m),
       {"map_error_anchored_p95_m", anchored_shown(&S::p95_m), "95th percentile after the start anchor, m"}},
      {anchored(&S::max_m),
       {"map_error_anchored_max_m", anchored_shown(&S::max_m), "largest distance after the start anchor, m"}},
  };
}

}  // namespace

std::vector<Eigen::Vector3f> LoadMapPoints(const std::filesystem::path& map_file) {
  if (!std::filesystem::is_regular_file(map_file)) throw InputError("map " + map_file.string() + ": no such file");
  const std::string extension = Lowercase(map_file.extension().string());
  if (extension == ".ply") return io::ReadPlyVertices(map_file);
  if (extension == ".pcd") {
    std::vector<Eigen::Vector4f> xyzi;
    io::LoadPcdXyzi(map_file, &xyzi);
    std::vector<Eigen::Vector3f> points;
    points.reserve(xyzi.size());
    for (const Eigen::Vector4f& p : xyzi) points.push_back(p.head<3>());
    return points;
  }
  throw InputError("map " + map_file.string() + ": unknown extension '" + extension + "' (expected .ply or .pcd)");
}

sim::World LoadWorldFile(const std::filesystem::path& world_file) {
  if (!std::filesystem::is_regular_file(world_file)) {
    throw InputError("world " + world_file.string() + ": no such file");
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(world_file.string());
  } catch (const YAML::Exception& e) {
    throw ConfigError(world_file.string(), e.mark.line >= 0 ? e.mark.line + 1 : 0, "", "YAML syntax: " + e.msg);
  }
  return sim::LoadWorld(root, world_file.string());
}

std::optional<std::filesystem::path> ResolveWorldFile(const std::string& world_option,
                                                      const std::filesystem::path& truth_file) {
  if (!world_option.empty()) {
    if (!std::filesystem::is_regular_file(world_option)) throw InputError("world " + world_option + ": no such file");
    return std::filesystem::path(world_option);
  }
  const std::filesystem::path beside = truth_file.parent_path() / "world.yaml";
  if (std::filesystem::is_regular_file(beside)) return beside;
  return std::nullopt;
}

MapEvaluation EvaluateMapFile(const std::filesystem::path& map_file, const std::filesystem::path& world_file,
                              const std::optional<Eigen::Isometry3d>& T_world_map,
                              const std::optional<Eigen::Isometry3d>& T_world_map_anchor) {
  const sim::World world = LoadWorldFile(world_file);
  if (world.size() == 0) throw InputError("world " + world_file.string() + ": has no primitives");
  std::vector<Eigen::Vector3f> points_map = LoadMapPoints(map_file);
  const auto distance = [&world](const Eigen::Vector3d& p_world) { return world.SurfaceDistance(p_world); };
  MapEvaluation result;
  result.map_file = map_file;
  result.world_file = world_file;
  try {
    result.unaligned = eval::ComputeMapError(points_map, distance);
    // The map moved by a transform: p_world = T_world_map p_map.
    const auto moved = [&](const Eigen::Isometry3d& T_world_map_d) {
      const Eigen::Isometry3f T = T_world_map_d.cast<float>();
      std::vector<Eigen::Vector3f> points_world(points_map.size());
      for (std::size_t i = 0; i < points_map.size(); ++i) points_world[i] = T * points_map[i];
      return eval::ComputeMapError(points_world, distance);
    };
    if (T_world_map) result.aligned = moved(*T_world_map);
    if (T_world_map_anchor) result.anchored = moved(*T_world_map_anchor);
  } catch (const InputError& e) {
    throw InputError("map " + map_file.string() + ": " + e.what());
  }
  return result;
}

eval::ReportExtras MapReportExtras(const MapEvaluation& evaluation) {
  eval::ReportExtras extras;
  extras.metrics = Metrics(evaluation);
  return extras;
}

}  // namespace unimap::cli
