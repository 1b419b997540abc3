#include "report/ReportData.hpp"

#include <optional>
#include <string>
#include <vector>

#include "eval/MetricsJson.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/TumTrajectory.hpp"
#include "report/Float32Table.hpp"
#include "report/LoopClosureLayer.hpp"
#include "report/RunSections.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kDegPerRad = 57.29577951308232;

// A trajectory for the 3D view: [t - t0, x, y, z] rows, positions moved by T.
Json Trajectory(const std::string& name, const std::string& label, const std::string& color,
                const std::vector<StampedPose>& poses, double t0, std::size_t budget, const Eigen::Isometry3d& T) {
  Float32Table table(4);
  for (const std::size_t i : Float32Table::Sample(poses.size(), budget)) {
    const Eigen::Vector3d p = T * poses[i].T_map_body.translation();
    table.AddRow({poses[i].time_s - t0, p.x(), p.y(), p.z()});
  }
  return {{"name", name}, {"label", label}, {"color", color}, {"count", table.rows()}, {"txyz", table.Base64()}};
}

Json Plot(const std::string& id, const std::string& title, const std::string& ylabel, const Json& labels,
          const Json& colors, const Json& dashed, const Float32Table& table) {
  return {{"id", id},         {"title", title},   {"ylabel", ylabel},     {"labels", labels},
          {"colors", colors}, {"dashed", dashed}, {"rows", table.rows()}, {"data", table.Base64()}};
}

// The error and position plots of an evaluation (truth frame, ATE-aligned estimate).
Json EvaluationPlots(const eval::TrajectoryEvaluation& ev, double t0, std::size_t budget) {
  Float32Table position(7), position_error(4), rotation_error(4);
  for (const std::size_t i : Float32Table::Sample(ev.errors.poses.size(), budget)) {
    const eval::PoseError& e = ev.errors.poses[i];
    const double t = e.time_s - t0;
    position.AddRow({t, e.p_aligned.x(), e.p_aligned.y(), e.p_aligned.z(), e.p_true.x(), e.p_true.y(), e.p_true.z()});
    position_error.AddRow({t, e.position_error_m.x(), e.position_error_m.y(), e.position_error_m.z()});
    const Eigen::Vector3d r = e.rotation_error_rad * kDegPerRad;
    rotation_error.AddRow({t, r.x(), r.y(), r.z()});
  }
  const Json xyz_colors = {"#d62728", "#2ca02c", "#1f77b4"};
  return Json::array(
      {Plot("position", "Position over time: ATE-aligned estimate (solid) and truth (dashed), truth frame",
            "position [m]", {"time [s]", "x", "y", "z", "x truth", "y truth", "z truth"},
            {"#d62728", "#2ca02c", "#1f77b4", "#7f0000", "#0b5d1e", "#0b3c6e"}, {false, false, false, true, true, true},
            position),
       Plot("position_error", "Position error (start-anchored estimate minus truth)", "error [m]",
            {"time [s]", "x", "y", "z"}, xyz_colors, {false, false, false}, position_error),
       Plot("rotation_error", "Rotation error log(q_est^-1 q_true) (start-anchored)", "error [deg]",
            {"time [s]", "roll", "pitch", "yaw"}, xyz_colors, {false, false, false}, rotation_error)});
}

// Without truth: the estimate's position over time (map frame).
Json EstimatePlots(const std::vector<StampedPose>& estimate, double t0, std::size_t budget) {
  Float32Table position(4);
  for (const std::size_t i : Float32Table::Sample(estimate.size(), budget)) {
    const Eigen::Vector3d p = estimate[i].T_map_body.translation();
    position.AddRow({estimate[i].time_s - t0, p.x(), p.y(), p.z()});
  }
  return Json::array({Plot("position", "Position over time (map frame)", "position [m]", {"time [s]", "x", "y", "z"},
                           {"#d62728", "#2ca02c", "#1f77b4"}, {false, false, false}, position)});
}

std::string Title(const RunFolder& f) {
  const auto text = [&f](const char* key) {  // "" when absent or not a string
    const auto it = f.run.find(key);
    return it != f.run.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  const std::string payload = text("payload");
  const std::string dataset = text("dataset");
  // The last two parts of a path ("unimap-demo/data"): enough to tell runs apart.
  const auto short_name = [](std::filesystem::path path) {
    if (path.filename().empty()) path = path.parent_path();  // "out/"
    const std::filesystem::path parent = path.parent_path().filename();
    return parent.empty() || parent == "." ? path.filename().string() : (parent / path.filename()).string();
  };
  if (payload.empty() && dataset.empty()) return "unimap report: " + short_name(f.folder);
  return "unimap run: " + (payload.empty() ? "" : payload + " on ") + short_name(dataset);
}

}  // namespace

ReportData BuildReportData(const RunFolder& f, const ReportOptions& options) {
  ReportData data;
  ReportCounts& counts = data.counts;
  Json payload = RunSections(f.run, f.metrics);
  Json notes = Json::array();
  for (const std::string& note : f.notes) notes.push_back(note);
  Json files = Json::array();
  const auto file = [&files](const char* label, const std::filesystem::path& path) {
    if (!path.empty()) files.push_back(Json{{"label", label}, {"path", path.string()}});
  };
  file("Estimate", f.estimate_file);
  file("Odometry (before optimisation)", f.odometry_file);
  file("Ground truth", f.truth_file);
  file("Map", f.map_file);
  file("Loop closures", f.loops_file);

  const std::vector<StampedPose> estimate =
      f.estimate_file.empty() ? std::vector<StampedPose>{} : io::ReadTumTrajectory(f.estimate_file);
  counts.estimate_poses = estimate.size();
  const double t0 = estimate.empty() ? 0.0 : estimate.front().time_s;
  std::optional<eval::TrajectoryEvaluation> evaluation;
  if (!f.truth_file.empty() && !estimate.empty()) {
    try {
      evaluation = eval::EvaluateTrajectory(estimate, io::ReadTumTrajectory(f.truth_file), options.evaluation);
    } catch (const InputError& e) {
      notes.push_back("Not evaluated against " + f.truth_file.string() + ": " + e.what());
    }
  }
  Json trajectories = Json::array();
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const std::size_t budget = options.plot_row_budget;
  if (!estimate.empty())
    trajectories.push_back(Trajectory("estimate", "estimate", "#e4572e", estimate, t0, budget, identity));
  if (!f.odometry_file.empty()) {
    trajectories.push_back(Trajectory("odometry", "odometry (before optimisation)", "#f2a541",
                                      io::ReadTumTrajectory(f.odometry_file), t0, budget, identity));
  }
  std::optional<Eigen::Isometry3d> T_world_map;
  Json plots = Json::array();
  if (evaluation) {
    T_world_map = evaluation->errors.alignment.T_target_source;
    trajectories.push_back(Trajectory("truth", "ground truth (ATE-aligned into the map frame)", "#17becf",
                                      evaluation->association.truth_span, t0, budget, T_world_map->inverse()));
    counts.truth_pairs = evaluation->errors.poses.size();
    if (f.metrics.empty())
      payload["metrics"] = RunSections({}, Json::parse(eval::MetricsToJson(evaluation->metrics)))["metrics"];
    plots = EvaluationPlots(*evaluation, t0, budget);
  } else if (!estimate.empty()) {
    plots = EstimatePlots(estimate, t0, budget);
  }
  counts.plots = plots.size();
  counts.plot_rows = plots.empty() ? 0 : plots[0]["rows"].get<std::size_t>();

  payload["title"] = Title(f);
  payload["folder"] = f.folder.string();
  payload["files"] = files;
  payload["map"] = f.map_file.empty() ? Json()
                                      : MapLayer(f.map_file, options.map_point_budget, T_world_map,
                                                 options.surface_distance, &counts.map);
  payload["trajectories"] = trajectories;
  payload["loops"] = f.loops_file.empty() ? Json() : LoopClosureLayer(f.loops_file, &counts.loop_closures);
  payload["plots"] = plots;
  payload["notes"] = notes;
  data.payload = std::move(payload);
  return data;
}

}  // namespace unimap::report
