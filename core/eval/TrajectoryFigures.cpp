#include "eval/TrajectoryFigures.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include <cairo.h>

#include "eval/LinePlot.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

constexpr LinePlot::Color kTruth{0.15, 0.15, 0.15};
constexpr LinePlot::Color kAnchored{0.84, 0.16, 0.16};
constexpr LinePlot::Color kAligned{0.12, 0.45, 0.86};
constexpr std::array<LinePlot::Color, 3> kAxisColors = {
    LinePlot::Color{0.84, 0.16, 0.16}, LinePlot::Color{0.12, 0.59, 0.24}, LinePlot::Color{0.12, 0.39, 0.86}};
constexpr int kWidth = 1000;
constexpr double kDegPerRad = 180.0 / M_PI;

// A white picture of width x height drawn by draw, as PNG bytes.
std::string RenderPng(int width, int height, const std::function<void(cairo_t*)>& draw) {
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());
  draw(cr.get());
  cairo_surface_flush(surface.get());
  std::string png;
  const cairo_status_t status = cairo_surface_write_to_png_stream(
      surface.get(),
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(std::string("PNG encoding failed: ") + cairo_status_to_string(status));
  return png;
}

// Top (axes 0, 1) or side (axes 0, 2) view of truth and both estimates at
// equal scale, the picture's height fitted to the data. The truth is drawn
// first and widest, so that estimates lying on it leave it visible.
Figure TrajectoryView(const TrajectoryEvaluation& ev, int a, int b, const std::string& file, const std::string& title,
                      const std::string& caption) {
  const char* names = "xyz";
  LinePlot plot;
  plot.SetTitle(title);
  plot.SetXLabel(std::string(1, names[a]) + " [m]");
  plot.SetYLabel(std::string(1, names[b]) + " [m]");
  plot.SetEqualAspect(true);
  LinePlot::Series truth{"truth", kTruth, {}, 4.0};
  for (const StampedPose& p : ev.association.truth_span) {
    const Eigen::Vector3d t = p.T_map_body.translation();
    truth.points.emplace_back(t[a], t[b]);
  }
  LinePlot::Series anchored{"estimate (start-anchored)", kAnchored, {}, 1.5};
  LinePlot::Series aligned{"estimate (ATE-aligned)", kAligned, {}, 1.5};
  for (const PoseError& e : ev.errors.poses) {
    anchored.points.emplace_back(e.p_anchored[a], e.p_anchored[b]);
    aligned.points.emplace_back(e.p_aligned[a], e.p_aligned[b]);
  }
  plot.AddSeries(std::move(truth));
  plot.AddSeries(std::move(aligned));
  plot.AddSeries(std::move(anchored));
  const int height = static_cast<int>(plot.FittedHeight(kWidth, 320, 900));
  return {file, caption, RenderPng(kWidth, height, [&](cairo_t* cr) {
            plot.Render(cr, {0, 0, kWidth, 1.0 * height});
          })};
}

// Three stacked panels of one vector series over time since the first pose.
Figure ErrorPanels(const TrajectoryEvaluation& ev, const std::function<Eigen::Vector3d(const PoseError&)>& value,
                   const std::array<std::string, 3>& names, const std::string& unit, const std::string& file,
                   const std::string& caption) {
  const int panel_h = 300;
  const double t0 = ev.errors.poses.front().time_s;
  const std::string png = RenderPng(kWidth, 3 * panel_h, [&](cairo_t* cr) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      LinePlot plot;
      plot.SetTitle(names[axis] + " error");
      plot.SetXLabel("time since start [s]");
      plot.SetYLabel("error [" + unit + "]");
      LinePlot::Series series{"", kAxisColors[axis], {}, 1.4};
      for (const PoseError& e : ev.errors.poses) {
        series.points.emplace_back(e.time_s - t0, value(e)[static_cast<int>(axis)]);
      }
      plot.AddSeries(std::move(series));
      plot.Render(cr, {0, static_cast<double>(axis) * panel_h, kWidth, panel_h});
    }
  });
  return {file, caption, png};
}

}  // namespace

std::vector<Figure> RenderTrajectoryFigures(const TrajectoryEvaluation& ev) {
  std::vector<Figure> figures;
  figures.push_back(
      TrajectoryView(ev, 0, 1, "trajectory_top.png", "Trajectory, top view (x-y)",
                     "Top view (equal scales): truth, start-anchored estimate and ATE-aligned estimate."));
  figures.push_back(
      TrajectoryView(ev, 0, 2, "trajectory_side.png", "Trajectory, side view (x-z)",
                     "Side view (equal scales): truth, start-anchored estimate and ATE-aligned estimate."));
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
