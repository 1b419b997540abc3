#pragma once
// A 2D line chart (axes, ticks with labels, grid, coloured series, legend,
// title) rendered into a region of a PlotCanvas.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "eval/PlotCanvas.hpp"

namespace unimap::eval {

class LinePlot {
 public:
  // One polyline; non-finite points break it into pieces.
  struct Series {
    std::string name;                     // legend text
    PlotCanvas::Color color;              // line colour
    std::vector<Eigen::Vector2d> points;  // data coordinates, drawn in order
  };

  void SetTitle(std::string title) { title_ = std::move(title); }
  void SetXLabel(std::string label) { x_label_ = std::move(label); }
  void SetYLabel(std::string label) { y_label_ = std::move(label); }
  // Same metres per pixel on both axes (trajectory views).
  void SetEqualAspect(bool equal) { equal_aspect_ = equal; }
  void AddSeries(Series series) { series_.push_back(std::move(series)); }

  // Draws everything inside area (legend in the plot corner covering the
  // fewest points). Axis ranges cover every finite point with a
  // 5 % margin (a zero-width range becomes +-1 around its value); ticks are
  // 1, 2 or 5 x 10^k apart.
  void Render(PlotCanvas* canvas, const PlotCanvas::Rect& area) const;

  // Tick values of a nice axis over [lo, hi] with about target ticks; the
  // range is widened to whole steps. step receives the spacing.
  static std::vector<double> NiceTicks(double& lo, double& hi, int target, double* step);
  // A tick label with as many decimals as step needs ("-0" printed as "0").
  static std::string FormatTick(double value, double step);

 private:
  std::string title_;
  std::string x_label_;
  std::string y_label_;
  bool equal_aspect_ = false;
  std::vector<Series> series_;
};

}  // namespace unimap::eval
