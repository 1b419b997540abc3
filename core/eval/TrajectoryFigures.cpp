#include "eval/TrajectoryFigures.hpp"

#include <array>
#include <cmath>
#include <functional>

#include "eval/LinePlot.hpp"
#include "eval/PngEncoder.hpp"

namespace unimap::eval {
namespace {

constexpr PlotCanvas::Color kBackground{255, 255, 255};
constexpr PlotCanvas::Color kTruth{40, 40, 40};
constexpr PlotCanvas::Color kAnchored{215, 40, 40};
constexpr PlotCanvas::Color kAligned{30, 100, 220};
constexpr std::array<PlotCanvas::Color, 3> kAxisColors = {
    PlotCanvas::Color{215, 40, 40}, PlotCanvas::Color{30, 150, 60}, PlotCanvas::Color{30, 100, 220}};
constexpr int kWidth = 1000;
constexpr double kDegPerRad = 180.0 / M_PI;

// Top (axes 0, 1) or side (axes 0, 2) view of truth and both estimates;
// equal_aspect: same scale on both axes (else the vertical axis is stretched).
Figure TrajectoryView(const TrajectoryEvaluation& ev, int a, int b, bool equal_aspect, int height,
                      const std::string& file, const std::string& title, const std::string& caption) {
  const char* names = "xyz";
  LinePlot plot;
  plot.SetTitle(title);
  plot.SetXLabel(std::string(1, names[a]) + " [m]");
  plot.SetYLabel(std::string(1, names[b]) + " [m]");
  plot.SetEqualAspect(equal_aspect);
  LinePlot::Series truth{"truth", kTruth, {}};
  for (const StampedPose& p : ev.association.truth_span) {
    const Eigen::Vector3d t = p.T_map_body.translation();
    truth.points.emplace_back(t[a], t[b]);
  }
  LinePlot::Series anchored{"estimate (start-anchored)", kAnchored, {}};
  LinePlot::Series aligned{"estimate (ATE-aligned)", kAligned, {}};
  for (const PoseError& e : ev.errors.poses) {
    anchored.points.emplace_back(e.p_anchored[a], e.p_anchored[b]);
    aligned.points.emplace_back(e.p_aligned[a], e.p_aligned[b]);
  }
  plot.AddSeries(std::move(truth));
  plot.AddSeries(std::move(aligned));
  plot.AddSeries(std::move(anchored));
  PlotCanvas canvas(kWidth, height, kBackground);
  plot.Render(&canvas, {0, 0, canvas.width(), canvas.height()});
  return {file, caption, EncodePng(canvas)};
}

// Three stacked panels of one vector series over time since the first pose.
Figure ErrorPanels(const TrajectoryEvaluation& ev, const std::function<Eigen::Vector3d(const PoseError&)>& value,
                   const std::array<std::string, 3>& names, const std::string& unit, const std::string& file,
                   const std::string& caption) {
  const int panel_h = 330;
  PlotCanvas canvas(kWidth, 3 * panel_h, kBackground);
  const double t0 = ev.errors.poses.front().time_s;
  for (int axis = 0; axis < 3; ++axis) {
    LinePlot plot;
    plot.SetTitle(names[static_cast<std::size_t>(axis)] + " error");
    plot.SetXLabel("time since start [s]");
    plot.SetYLabel("error [" + unit + "]");
    LinePlot::Series series{names[static_cast<std::size_t>(axis)], kAxisColors[static_cast<std::size_t>(axis)], {}};
    for (const PoseError& e : ev.errors.poses) series.points.emplace_back(e.time_s - t0, value(e)[axis]);
    plot.AddSeries(std::move(series));
    plot.Render(&canvas, {0, axis * panel_h, canvas.width(), panel_h});
  }
  return {file, caption, EncodePng(canvas)};
}

}  // namespace

std::vector<Figure> RenderTrajectoryFigures(const TrajectoryEvaluation& ev) {
  std::vector<Figure> figures;
  figures.push_back(TrajectoryView(ev, 0, 1, true, 800, "trajectory_top.png", "Trajectory top view (x-y)",
                                   "Top view (equal scales): truth, start-anchored estimate and ATE-aligned estimate."));
  figures.push_back(TrajectoryView(ev, 0, 2, false, 500, "trajectory_side.png", "Side view (x-z, z stretched)",
                                   "Side view (z axis stretched to show height errors): truth, start-anchored "
                                   "estimate and ATE-aligned estimate."));
  figures.push_back(ErrorPanels(
      ev, [](const PoseError& e) { return e.position_error_m; }, {"x", "y", "z"}, "m", "position_error.png",
      "Position error (start-anchored estimate minus truth) per axis over time."));
  figures.push_back(ErrorPanels(
      ev, [](const PoseError& e) -> Eigen::Vector3d { return e.rotation_error_rad * kDegPerRad; },
      {"roll", "pitch", "yaw"}, "deg", "rotation_error.png",
      "Rotation error log(q_est^-1 q_true) per component over time (start-anchored)."));
  return figures;
}

}  // namespace unimap::eval
