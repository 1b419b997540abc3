#include "eval/LinePlot.hpp"

#include <gtest/gtest.h>

namespace unimap::eval {
namespace {

constexpr PlotCanvas::Color kWhite{255, 255, 255};
constexpr PlotCanvas::Color kSeries{200, 10, 10};

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

TEST(LinePlotTest, DrawsSeriesInsideTheAreaAndLeavesTheRestAlone) {
  PlotCanvas canvas(400, 300, kWhite);
  LinePlot plot;
  plot.SetTitle("t");
  plot.AddSeries({"s", kSeries, {{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}}});
  plot.Render(&canvas, {0, 0, 400, 250});
  int series_pixels = 0;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (canvas.At(x, y) == kSeries) {
        ++series_pixels;
        EXPECT_LT(y, 250);
      }
    }
  }
  EXPECT_GT(series_pixels, 200);  // two long strokes plus the legend sample
  for (int x = 0; x < 400; ++x) EXPECT_EQ(canvas.At(x, 270), kWhite);
}

TEST(LinePlotTest, EqualAspectKeepsCirclesRound) {
  // A unit square drawn in a wide area with equal aspect spans as many
  // columns as rows.
  PlotCanvas canvas(800, 400, kWhite);
  LinePlot plot;
  plot.SetEqualAspect(true);
  plot.AddSeries({"", kSeries, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}});
  plot.Render(&canvas, {0, 0, 800, 400});
  int min_x = 800, max_x = -1, min_y = 400, max_y = -1;
  for (int y = 0; y < 400; ++y) {
    for (int x = 0; x < 800; ++x) {
      if (!(canvas.At(x, y) == kSeries)) continue;
      if (x > 700 && y < 80) continue;  // legend sample
      min_x = std::min(min_x, x);
      max_x = std::max(max_x, x);
      min_y = std::min(min_y, y);
      max_y = std::max(max_y, y);
    }
  }
  EXPECT_NEAR(max_x - min_x, max_y - min_y, 2);
}

}  // namespace
}  // namespace unimap::eval
