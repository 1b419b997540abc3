#include "eval/LinePlot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace unimap::eval {
namespace {

constexpr PlotCanvas::Color kBlack{0, 0, 0};
constexpr PlotCanvas::Color kGrid{225, 225, 225};
constexpr PlotCanvas::Color kLegendBorder{150, 150, 150};
constexpr PlotCanvas::Color kWhite{255, 255, 255};
constexpr int kTextScale = 2;   // tick labels, axis labels, legend
constexpr int kTitleScale = 3;  // title

// Data range [lo, hi] of one axis; degenerate ranges widened.
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  void Finish() {
    if (!(lo <= hi)) {
      lo = 0.0;
      hi = 1.0;
    }
    if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
      lo -= 1.0;
      hi += 1.0;
      return;
    }
    const double pad = 0.05 * (hi - lo);
    lo -= pad;
    hi += pad;
  }
};

}  // namespace

std::vector<double> LinePlot::NiceTicks(double& lo, double& hi, int target, double* step) {
  const double raw = (hi - lo) / std::max(1, target);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double nice = 10.0 * magnitude;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) {
      nice = m * magnitude;
      break;
    }
  }
  lo = std::floor(lo / nice) * nice;
  hi = std::ceil(hi / nice) * nice;
  std::vector<double> ticks;
  const long first = std::lround(lo / nice);
  const long last = std::lround(hi / nice);
  for (long i = first; i <= last; ++i) ticks.push_back(static_cast<double>(i) * nice);
  *step = nice;
  return ticks;
}

std::string LinePlot::FormatTick(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  std::string text = buffer;
  if (text.find_first_not_of("-0.") == std::string::npos) text = text.substr(text[0] == '-' ? 1 : 0);
  return text;
}

void LinePlot::Render(PlotCanvas* canvas, const PlotCanvas::Rect& area) const {
  Range xr;
  Range yr;
  for (const Series& s : series_) {
    for (const Eigen::Vector2d& p : s.points) {
      if (!p.allFinite()) continue;
      xr.Add(p.x());
      yr.Add(p.y());
    }
  }
  xr.Finish();
  yr.Finish();

  // Layout: title row, y-label row, plot, x tick labels, x label.
  const int text_h = PlotCanvas::TextHeight(kTextScale);
  const int title_h = PlotCanvas::TextHeight(kTitleScale);
  const int top = area.y + 8 + title_h + 8 + text_h + 6;
  const int bottom = area.y + area.height - (8 + text_h + 8 + text_h + 6);
  // Left margin from the widest y tick label (estimated on the padded range first).
  int label_w = 0;
  {
    double lo = yr.lo;
    double hi = yr.hi;
    double step = 1.0;
    for (double v : NiceTicks(lo, hi, std::max(2, (bottom - top) / 45), &step)) {
      label_w = std::max(label_w, PlotCanvas::TextWidth(FormatTick(v, step), kTextScale));
    }
  }
  const int left = area.x + 12 + label_w + 8;
  const int right = area.x + area.width - 16;
  const PlotCanvas::Rect plot{left, top, std::max(1, right - left), std::max(1, bottom - top)};

  // Equal aspect: widen the range of the axis that has room to spare.
  if (equal_aspect_) {
    // Data units per pixel step, as used by to_px / to_py below.
    const double cols = std::max(1, plot.width - 1);
    const double rows = std::max(1, plot.height - 1);
    const double sx = (xr.hi - xr.lo) / cols;
    const double sy = (yr.hi - yr.lo) / rows;
    if (sx > sy) {
      const double c = 0.5 * (yr.lo + yr.hi);
      yr.lo = c - 0.5 * sx * rows;
      yr.hi = c + 0.5 * sx * rows;
    } else {
      const double c = 0.5 * (xr.lo + xr.hi);
      xr.lo = c - 0.5 * sy * cols;
      xr.hi = c + 0.5 * sy * cols;
    }
  }
  // Tick positions within the (unchanged) range; only ticks inside are drawn.
  double x_step = 1.0;
  double y_step = 1.0;
  double x_lo = xr.lo, x_hi = xr.hi, y_lo = yr.lo, y_hi = yr.hi;
  const std::vector<double> x_ticks = NiceTicks(x_lo, x_hi, std::max(2, plot.width / 110), &x_step);
  const std::vector<double> y_ticks = NiceTicks(y_lo, y_hi, std::max(2, plot.height / 45), &y_step);
  const auto to_px = [&](double x) { return plot.x + (x - xr.lo) / (xr.hi - xr.lo) * (plot.width - 1); };
  const auto to_py = [&](double y) {
    return plot.y + plot.height - 1 - (y - yr.lo) / (yr.hi - yr.lo) * (plot.height - 1);
  };

  canvas->FillRect(plot, kWhite);
  for (const double v : x_ticks) {
    if (v < xr.lo || v > xr.hi) continue;
    const double px = to_px(v);
    canvas->DrawLine(px, plot.y, px, plot.y + plot.height - 1, kGrid, 1, &plot);
    canvas->DrawLine(px, plot.y + plot.height, px, plot.y + plot.height + 4, kBlack, 1);
    const std::string label = FormatTick(v, x_step);
    canvas->DrawText(static_cast<int>(std::lround(px)) - PlotCanvas::TextWidth(label, kTextScale) / 2,
                     plot.y + plot.height + 8, label, kBlack, kTextScale);
  }
  for (const double v : y_ticks) {
    if (v < yr.lo || v > yr.hi) continue;
    const double py = to_py(v);
    canvas->DrawLine(plot.x, py, plot.x + plot.width - 1, py, kGrid, 1, &plot);
    canvas->DrawLine(plot.x - 5, py, plot.x - 1, py, kBlack, 1);
    const std::string label = FormatTick(v, y_step);
    canvas->DrawText(plot.x - 8 - PlotCanvas::TextWidth(label, kTextScale),
                     static_cast<int>(std::lround(py)) - text_h / 2, label, kBlack, kTextScale);
  }
  // Series, clipped to the plot.
  for (const Series& s : series_) {
    for (std::size_t k = 1; k < s.points.size(); ++k) {
      const Eigen::Vector2d& a = s.points[k - 1];
      const Eigen::Vector2d& b = s.points[k];
      if (!a.allFinite() || !b.allFinite()) continue;
      canvas->DrawLine(to_px(a.x()), to_py(a.y()), to_px(b.x()), to_py(b.y()), s.color, 2, &plot);
    }
    if (s.points.size() == 1 && s.points[0].allFinite()) {
      const double px = to_px(s.points[0].x());
      const double py = to_py(s.points[0].y());
      canvas->DrawLine(px, py, px, py, s.color, 4, &plot);
    }
  }
  canvas->StrokeRect(plot, kBlack);

  // Title (centred), y label (above the axis), x label (centred below the ticks).
  canvas->DrawText(area.x + (area.width - PlotCanvas::TextWidth(title_, kTitleScale)) / 2, area.y + 8,
                   title_, kBlack, kTitleScale);
  canvas->DrawText(plot.x, plot.y - 6 - text_h, y_label_, kBlack, kTextScale);
  canvas->DrawText(plot.x + (plot.width - PlotCanvas::TextWidth(x_label_, kTextScale)) / 2,
                   plot.y + plot.height + 8 + text_h + 8, x_label_, kBlack, kTextScale);

  // Legend in the plot corner covering the fewest data points (top-right first on ties).
  if (series_.empty()) return;
  int legend_w = 0;
  for (const Series& s : series_) legend_w = std::max(legend_w, PlotCanvas::TextWidth(s.name, kTextScale));
  const int row_h = text_h + 6;
  const int box_w = legend_w + 48;
  const int box_h = static_cast<int>(series_.size()) * row_h + 8;
  const int box_left = plot.x + 8;
  const int box_right = plot.x + plot.width - box_w - 8;
  const int box_top = plot.y + 8;
  const int box_bottom = plot.y + plot.height - box_h - 8;
  const PlotCanvas::Rect corners[4] = {{box_right, box_top, box_w, box_h},
                                       {box_left, box_top, box_w, box_h},
                                       {box_right, box_bottom, box_w, box_h},
                                       {box_left, box_bottom, box_w, box_h}};
  int covered[4] = {0, 0, 0, 0};
  for (const Series& s : series_) {
    for (const Eigen::Vector2d& p : s.points) {
      if (!p.allFinite()) continue;
      const int px = static_cast<int>(std::lround(to_px(p.x())));
      const int py = static_cast<int>(std::lround(to_py(p.y())));
      for (int c = 0; c < 4; ++c) covered[c] += corners[c].Contains(px, py) ? 1 : 0;
    }
  }
  const PlotCanvas::Rect box = corners[std::min_element(covered, covered + 4) - covered];
  canvas->FillRect(box, kWhite);
  canvas->StrokeRect(box, kLegendBorder);
  for (std::size_t i = 0; i < series_.size(); ++i) {
    const int y = box.y + 4 + static_cast<int>(i) * row_h;
    const double line_y = y + text_h / 2.0;
    canvas->DrawLine(box.x + 6, line_y, box.x + 32, line_y, series_[i].color, 3);
    canvas->DrawText(box.x + 40, y, series_[i].name, kBlack, kTextScale);
  }
}

}  // namespace unimap::eval
