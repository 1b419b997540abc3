#include "eval/PlotCanvas.hpp"

#include <algorithm>
#include <cmath>

#include "eval/BitmapFont.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

// Liang-Barsky: clips the segment p0 -> p1 to [xmin, xmax] x [ymin, ymax].
// Returns false when nothing is left.
bool ClipSegment(double& x0, double& y0, double& x1, double& y1, double xmin, double ymin, double xmax,
                 double ymax) {
  const double dx = x1 - x0;
  const double dy = y1 - y0;
  double t0 = 0.0;
  double t1 = 1.0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - xmin, xmax - x0, y0 - ymin, ymax - y0};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;  // parallel and outside
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  const double sx = x0;
  const double sy = y0;
  x0 = sx + t0 * dx;
  y0 = sy + t0 * dy;
  x1 = sx + t1 * dx;
  y1 = sy + t1 * dy;
  return true;
}

}  // namespace

PlotCanvas::PlotCanvas(int width, int height, Color background) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw InputError("plot canvas size " + std::to_string(width) + " x " + std::to_string(height) +
                     " is out of range");
  }
  rgb_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  FillRect({0, 0, width, height}, background);
}

PlotCanvas::Color PlotCanvas::At(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 3;
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void PlotCanvas::SetPixel(int x, int y, Color color, const Rect* clip) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  if (clip != nullptr && !clip->Contains(x, y)) return;
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 3;
  rgb_[i] = color.r;
  rgb_[i + 1] = color.g;
  rgb_[i + 2] = color.b;
}

void PlotCanvas::FillRect(const Rect& rect, Color color) {
  const int x0 = std::max(rect.x, 0);
  const int y0 = std::max(rect.y, 0);
  const int x1 = std::min(rect.x + rect.width, width_);
  const int y1 = std::min(rect.y + rect.height, height_);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) SetPixel(x, y, color);
  }
}

void PlotCanvas::StrokeRect(const Rect& rect, Color color) {
  const int right = rect.x + rect.width - 1;
  const int bottom = rect.y + rect.height - 1;
  for (int x = rect.x; x <= right; ++x) {
    SetPixel(x, rect.y, color);
    SetPixel(x, bottom, color);
  }
  for (int y = rect.y; y <= bottom; ++y) {
    SetPixel(rect.x, y, color);
    SetPixel(right, y, color);
  }
}

void PlotCanvas::DrawLine(double x0, double y0, double x1, double y1, Color color, int thickness,
                          const Rect* clip) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return;
  const Rect bounds = clip != nullptr ? *clip : Rect{0, 0, width_, height_};
  // Clip first (with a margin for the thickness) so far-away points cost nothing.
  const double margin = static_cast<double>(thickness);
  if (!ClipSegment(x0, y0, x1, y1, bounds.x - margin, bounds.y - margin,
                   bounds.x + bounds.width - 1 + margin, bounds.y + bounds.height - 1 + margin)) {
    return;
  }
  // DDA: one step per pixel along the major axis, stamping a square brush.
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0))));
  const int lo = -(thickness - 1) / 2;
  const int hi = thickness / 2;
  for (int s = 0; s <= steps; ++s) {
    const double t = steps == 0 ? 0.0 : static_cast<double>(s) / steps;
    const int cx = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int cy = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    for (int dy = lo; dy <= hi; ++dy) {
      for (int dx = lo; dx <= hi; ++dx) SetPixel(cx + dx, cy + dy, color, &bounds);
    }
  }
}

void PlotCanvas::DrawText(int x, int y, const std::string& text, Color color, int scale) {
  int pen_x = x;
  for (const char c : text) {
    const auto& rows = BitmapFont::Glyph(c);
    for (int r = 0; r < BitmapFont::kGlyphHeight; ++r) {
      for (int col = 0; col < BitmapFont::kGlyphWidth; ++col) {
        if ((rows[static_cast<std::size_t>(r)] >> (BitmapFont::kGlyphWidth - 1 - col) & 1u) == 0) continue;
        FillRect({pen_x + col * scale, y + r * scale, scale, scale}, color);
      }
    }
    pen_x += BitmapFont::kAdvance * scale;
  }
}

int PlotCanvas::TextWidth(const std::string& text, int scale) {
  if (text.empty()) return 0;
  return (static_cast<int>(text.size()) * BitmapFont::kAdvance - 1) * scale;
}

int PlotCanvas::TextHeight(int scale) { return BitmapFont::kGlyphHeight * scale; }

}  // namespace unimap::eval
