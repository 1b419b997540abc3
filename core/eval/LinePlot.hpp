#pragma once
// A 2D line chart (axes, ticks with labels, grid, coloured series, legend,
// title) drawn with cairo (real fonts, anti-aliased lines) into a region of
// a cairo context.
#include <string>
#include <vector>

#include <Eigen/Core>

typedef struct _cairo cairo_t;

namespace unimap::eval {

class LinePlot {
 public:
  struct Color {
    double r, g, b;  // 0..1
  };
  // One polyline; non-finite points break it into pieces.
  struct Series {
    std::string name;                     // legend text
    Color color;                          // line colour
    std::vector<Eigen::Vector2d> points;  // data coordinates, drawn in order
    double width_px = 1.6;                // line width
  };
  // A region of the drawing, pixels.
  struct Rect {
    double x, y, width, height;
  };

  void SetTitle(std::string title) { title_ = std::move(title); }
  void SetXLabel(std::string label) { x_label_ = std::move(label); }
  void SetYLabel(std::string label) { y_label_ = std::move(label); }
  // Same metres per pixel on both axes (trajectory views).
  void SetEqualAspect(bool equal) { equal_aspect_ = equal; }
  // Series are drawn in the order added (later ones on top).
  void AddSeries(Series series) { series_.push_back(std::move(series)); }

  // Draws everything inside area (legend in the plot corner covering the
  // fewest points). Axis ranges cover every finite point with a 5 % margin
  // (a zero-width range becomes +-1 around its value); ticks are 1, 2 or 5
  // x 10^k apart.
  void Render(cairo_t* cr, const Rect& area) const;

  // The height an area of the given width needs so that, at equal scale,
  // the data fits it with the least empty space, within [min_height,
  // max_height] (title, labels and margins included).
  double FittedHeight(double width, double min_height, double max_height) const;

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
