#include "eval/LinePlot.hpp"

#include <algorithm>
#include <cstdint>

#include <cairo.h>
#include <gtest/gtest.h>

namespace unimap::eval {
namespace {

TEST(LinePlotTest, NiceTicksUseOneTwoFiveSteps) {
  double lo = 0.3;
  double hi = 9.2;
  double step = 0.0;
  const std::vector<double> ticks = LinePlot::NiceTicks(lo, hi, 5, &step);
  EXPECT_DOUBLE_EQ(step, 2.0);
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_DOUBLE_EQ(hi, 10.0);
  ASSERT_EQ(ticks.size(), 6u);
  EXPECT_DOUBLE_EQ(ticks[3], 6.0);
  lo = -0.013;
  hi = 0.041;
  LinePlot::NiceTicks(lo, hi, 5, &step);
  EXPECT_DOUBLE_EQ(step, 0.02);
  EXPECT_DOUBLE_EQ(lo, -0.02);
}

TEST(LinePlotTest, FormatsTicksWithTheStepsDecimals) {
  EXPECT_EQ(LinePlot::FormatTick(2.0, 1.0), "2");
  EXPECT_EQ(LinePlot::FormatTick(0.25, 0.05), "0.25");
  EXPECT_EQ(LinePlot::FormatTick(-1e-17, 0.5), "0.0");
  EXPECT_EQ(LinePlot::FormatTick(150.0, 50.0), "150");
}

// An RGB24 cairo image of width x height, white, that plots draw into.
class Image {
 public:
  Image(int width, int height)
      : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)), cr_(cairo_create(surface_)) {
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_paint(cr_);
  }
  ~Image() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  cairo_t* cr() { return cr_; }
  // The pixel's 0xRRGGBB.
  std::uint32_t At(int x, int y) {
    cairo_surface_flush(surface_);
    const unsigned char* row = cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
    return reinterpret_cast<const std::uint32_t*>(row)[x] & 0xffffffu;
  }
  // Whether the pixel is mostly the series colour (pure red, anti-aliased edges count when red dominates).
  bool IsSeries(int x, int y) {
    const std::uint32_t p = At(x, y);
    const int r = static_cast<int>(p >> 16 & 255), g = static_cast<int>(p >> 8 & 255), b = static_cast<int>(p & 255);
    return r > 150 && g < 90 && b < 90;
  }

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

constexpr LinePlot::Color kRed{1.0, 0.0, 0.0};

TEST(LinePlotTest, DrawsSeriesInsideTheAreaAndLeavesTheRestAlone) {
  Image image(400, 300);
  LinePlot plot;
  plot.SetTitle("t");
  plot.AddSeries({"s", kRed, {{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}}, 2.0});
  plot.Render(image.cr(), {0, 0, 400, 250});
  int series_pixels = 0;
  for (int y = 0; y < 300; ++y) {
    for (int x = 0; x < 400; ++x) {
      if (!image.IsSeries(x, y)) continue;
      ++series_pixels;
      EXPECT_LT(y, 250);
    }
  }
  EXPECT_GT(series_pixels, 400);  // two long strokes of 2 px plus the legend sample
  for (int x = 0; x < 400; ++x) EXPECT_EQ(image.At(x, 270), 0xffffffu) << x;
}

TEST(LinePlotTest, DrawsTextWithAFont) {
  // Title and tick labels leave dark, anti-aliased (grey) pixels above the plot.
  Image image(400, 300);
  LinePlot plot;
  plot.SetTitle("Position error over time");
  plot.AddSeries({"", kRed, {{0.0, 0.0}, {1.0, 1.0}}});
  plot.Render(image.cr(), {0, 0, 400, 300});
  int dark = 0, grey = 0;
  for (int y = 0; y < 36; ++y) {
    for (int x = 0; x < 400; ++x) {
      const int v = static_cast<int>(image.At(x, y) & 255);
      dark += v < 80 ? 1 : 0;
      grey += v >= 80 && v < 230 ? 1 : 0;
    }
  }
  EXPECT_GT(dark, 50);
  EXPECT_GT(grey, 20);  // anti-aliasing: a bitmap font would have none
}

TEST(LinePlotTest, EqualAspectKeepsSquaresSquare) {
  // A unit square drawn in a wide area with equal aspect spans as many
  // columns as rows.
  Image image(800, 400);
  LinePlot plot;
  plot.SetEqualAspect(true);
  plot.AddSeries({"", kRed, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, 1.0});
  plot.Render(image.cr(), {0, 0, 800, 400});
  int min_x = 800, max_x = -1, min_y = 400, max_y = -1;
  for (int y = 0; y < 400; ++y) {
    for (int x = 0; x < 800; ++x) {
      if (!image.IsSeries(x, y)) continue;
      min_x = std::min(min_x, x);
      max_x = std::max(max_x, x);
      min_y = std::min(min_y, y);
      max_y = std::max(max_y, y);
    }
  }
  EXPECT_GT(max_x - min_x, 100);
  EXPECT_NEAR(max_x - min_x, max_y - min_y, 2);
}

TEST(LinePlotTest, FittedHeightFollowsTheDataAspect) {
  LinePlot wide;
  wide.AddSeries({"", kRed, {{0, 0}, {100, 5}}});
  LinePlot square;
  square.AddSeries({"", kRed, {{0, 0}, {10, 10}}});
  EXPECT_EQ(wide.FittedHeight(1000, 300, 900), 300);    // a tunnel: the least height
  EXPECT_EQ(square.FittedHeight(1000, 300, 900), 900);  // a square: capped
  LinePlot half;
  half.AddSeries({"", kRed, {{0, 0}, {10, 4}}});
  const double h = half.FittedHeight(1000, 100, 2000);
  EXPECT_GT(h, 400);
  EXPECT_LT(h, 600);
}

}  // namespace
}  // namespace unimap::eval
