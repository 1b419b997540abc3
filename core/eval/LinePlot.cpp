#include "eval/LinePlot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <cairo.h>

namespace unimap::eval {
namespace {

constexpr const char* kFont = "DejaVu Sans";  // fonts-dejavu-core; fontconfig falls back to any sans
constexpr double kTickFont = 13.0;
constexpr double kLabelFont = 14.0;
constexpr double kTitleFont = 17.0;
// Margins around the plot (pixels) besides the tick labels' width.
constexpr double kTop = 12.0 + kTitleFont + 12.0;
constexpr double kBottom = 8.0 + kTickFont + 10.0 + kLabelFont + 10.0;
constexpr double kLeftBesideTicks = 10.0 + kLabelFont + 10.0 + 8.0;
constexpr double kRight = 18.0;

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

void Ranges(const std::vector<LinePlot::Series>& series, Range* xr, Range* yr) {
  for (const LinePlot::Series& s : series) {
    for (const Eigen::Vector2d& p : s.points) {
      if (!p.allFinite()) continue;
      xr->Add(p.x());
      yr->Add(p.y());
    }
  }
  xr->Finish();
  yr->Finish();
}

void SetColor(cairo_t* cr, const LinePlot::Color& c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

double TextWidth(cairo_t* cr, const std::string& text, double size) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// Text with its left end at x and its baseline at y.
void Text(cairo_t* cr, double x, double y, const std::string& text, double size) {
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

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

double LinePlot::FittedHeight(double width, double min_height, double max_height) const {
  Range xr, yr;
  Ranges(series_, &xr, &yr);
  const double plot_width = width - kLeftBesideTicks - 50.0 - kRight;  // 50: typical tick label width
  const double height = plot_width * (yr.hi - yr.lo) / (xr.hi - xr.lo) + kTop + kBottom;
  return std::clamp(std::round(height), min_height, max_height);
}

void LinePlot::Render(cairo_t* cr, const Rect& area) const {
  Range xr, yr;
  Ranges(series_, &xr, &yr);
  cairo_save(cr);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

  // Left margin from the widest y tick label (estimated on the padded range first).
  const double top = area.y + kTop;
  const double bottom = area.y + area.height - kBottom;
  double label_w = 0.0;
  {
    double lo = yr.lo, hi = yr.hi, step = 1.0;
    for (const double v : NiceTicks(lo, hi, std::max(2, static_cast<int>((bottom - top) / 45)), &step)) {
      label_w = std::max(label_w, TextWidth(cr, FormatTick(v, step), kTickFont));
    }
  }
  const Rect plot{area.x + kLeftBesideTicks + label_w, top,
                  std::max(1.0, area.width - kLeftBesideTicks - label_w - kRight), std::max(1.0, bottom - top)};
  // Equal aspect: widen the range of the axis that has room to spare.
  if (equal_aspect_) {
    const double sx = (xr.hi - xr.lo) / plot.width;
    const double sy = (yr.hi - yr.lo) / plot.height;
    if (sx > sy) {
      const double c = 0.5 * (yr.lo + yr.hi);
      yr.lo = c - 0.5 * sx * plot.height;
      yr.hi = c + 0.5 * sx * plot.height;
    } else {
      const double c = 0.5 * (xr.lo + xr.hi);
      xr.lo = c - 0.5 * sy * plot.width;
      xr.hi = c + 0.5 * sy * plot.width;
    }
  }
  double x_step = 1.0, y_step = 1.0;
  double x_lo = xr.lo, x_hi = xr.hi, y_lo = yr.lo, y_hi = yr.hi;
  const std::vector<double> x_ticks = NiceTicks(x_lo, x_hi, std::max(2, static_cast<int>(plot.width / 110)), &x_step);
  const std::vector<double> y_ticks = NiceTicks(y_lo, y_hi, std::max(2, static_cast<int>(plot.height / 45)), &y_step);
  const auto to_px = [&](double x) { return plot.x + (x - xr.lo) / (xr.hi - xr.lo) * plot.width; };
  const auto to_py = [&](double y) { return plot.y + plot.height - (y - yr.lo) / (yr.hi - yr.lo) * plot.height; };

  // Grid, ticks and their labels.
  cairo_set_line_width(cr, 1.0);
  for (const double v : x_ticks) {
    if (v < xr.lo || v > xr.hi) continue;
    const double px = std::round(to_px(v)) + 0.5;
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px, plot.y);
    cairo_line_to(cr, px, plot.y + plot.height);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    const std::string label = FormatTick(v, x_step);
    Text(cr, px - TextWidth(cr, label, kTickFont) / 2, plot.y + plot.height + 8 + kTickFont, label, kTickFont);
  }
  for (const double v : y_ticks) {
    if (v < yr.lo || v > yr.hi) continue;
    const double py = std::round(to_py(v)) + 0.5;
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, plot.x, py);
    cairo_line_to(cr, plot.x + plot.width, py);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    const std::string label = FormatTick(v, y_step);
    Text(cr, plot.x - 8 - TextWidth(cr, label, kTickFont), py + kTickFont * 0.35, label, kTickFont);
  }
  // Series, clipped to the plot.
  cairo_save(cr);
  cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const Series& s : series_) {
    SetColor(cr, s.color);
    cairo_set_line_width(cr, s.width_px);
    bool pen_down = false;
    for (const Eigen::Vector2d& p : s.points) {
      if (!p.allFinite()) {
        pen_down = false;
        continue;
      }
      if (pen_down)
        cairo_line_to(cr, to_px(p.x()), to_py(p.y()));
      else
        cairo_move_to(cr, to_px(p.x()), to_py(p.y()));
      pen_down = true;
    }
    if (s.points.size() == 1) cairo_line_to(cr, to_px(s.points[0].x()), to_py(s.points[0].y()));  // a dot
    cairo_stroke(cr);
  }
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, std::round(plot.x) + 0.5, std::round(plot.y) + 0.5, std::round(plot.width),
                  std::round(plot.height));
  cairo_stroke(cr);

  // Title (centred), y label (rotated, left), x label (centred below the ticks).
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  Text(cr, area.x + (area.width - TextWidth(cr, title_, kTitleFont)) / 2, area.y + 12 + kTitleFont, title_, kTitleFont);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  Text(cr, plot.x + (plot.width - TextWidth(cr, x_label_, kLabelFont)) / 2, area.y + area.height - 10, x_label_,
       kLabelFont);
  cairo_save(cr);
  cairo_translate(cr, area.x + 10 + kLabelFont, plot.y + (plot.height + TextWidth(cr, y_label_, kLabelFont)) / 2);
  cairo_rotate(cr, -M_PI / 2);
  Text(cr, 0, 0, y_label_, kLabelFont);
  cairo_restore(cr);

  // Legend in the plot corner covering the fewest data points (top-right first on ties).
  std::vector<const Series*> named;
  for (const Series& s : series_) {
    if (!s.name.empty()) named.push_back(&s);
  }
  if (!named.empty()) {
    double legend_w = 0.0;
    for (const Series* s : named) legend_w = std::max(legend_w, TextWidth(cr, s->name, kTickFont));
    const double row_h = kTickFont + 7, box_w = legend_w + 50, box_h = static_cast<double>(named.size()) * row_h + 8;
    const double left = plot.x + 8, right = plot.x + plot.width - box_w - 8;
    const double upper = plot.y + 8, lower = plot.y + plot.height - box_h - 8;
    const Rect corners[4] = {{right, upper, box_w, box_h},
                             {left, upper, box_w, box_h},
                             {right, lower, box_w, box_h},
                             {left, lower, box_w, box_h}};
    int covered[4] = {0, 0, 0, 0};
    for (const Series& s : series_) {
      for (const Eigen::Vector2d& p : s.points) {
        if (!p.allFinite()) continue;
        const double px = to_px(p.x()), py = to_py(p.y());
        for (int c = 0; c < 4; ++c) {
          const Rect& r = corners[c];
          covered[c] += px >= r.x && px < r.x + r.width && py >= r.y && py < r.y + r.height ? 1 : 0;
        }
      }
    }
    const Rect box = corners[std::min_element(covered, covered + 4) - covered];
    cairo_rectangle(cr, box.x, box.y, box.width, box.height);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_stroke(cr);
    for (std::size_t i = 0; i < named.size(); ++i) {
      const double y = box.y + 4 + static_cast<double>(i) * row_h + row_h / 2;
      SetColor(cr, named[i]->color);
      cairo_set_line_width(cr, std::max(2.5, named[i]->width_px));
      cairo_move_to(cr, box.x + 8, y);
      cairo_line_to(cr, box.x + 36, y);
      cairo_stroke(cr);
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      Text(cr, box.x + 42, y + kTickFont * 0.35, named[i]->name, kTickFont);
    }
  }
  cairo_restore(cr);
}

}  // namespace unimap::eval
