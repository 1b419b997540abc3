#include "eval/PlotCanvas.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "eval/BitmapFont.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

constexpr PlotCanvas::Color kWhite{255, 255, 255};
constexpr PlotCanvas::Color kRed{255, 0, 0};

int CountColor(const PlotCanvas& c, PlotCanvas::Color color) {
  int n = 0;
  for (int y = 0; y < c.height(); ++y) {
    for (int x = 0; x < c.width(); ++x) n += c.At(x, y) == color ? 1 : 0;
  }
  return n;
}

TEST(PlotCanvasTest, HorizontalDiagonalAndThickLines) {
  PlotCanvas c(20, 20, kWhite);
  c.DrawLine(2, 5, 11, 5, kRed, 1);
  EXPECT_EQ(CountColor(c, kRed), 10);
  for (int x = 2; x <= 11; ++x) EXPECT_EQ(c.At(x, 5), kRed);
  PlotCanvas d(20, 20, kWhite);
  d.DrawLine(0, 0, 9, 9, kRed, 1);
  EXPECT_EQ(CountColor(d, kRed), 10);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(d.At(i, i), kRed);
  PlotCanvas t(20, 20, kWhite);
  t.DrawLine(5, 10, 14, 10, kRed, 3);
  EXPECT_EQ(CountColor(t, kRed), 36);  // 3x3 brush: columns 4..15, rows 9..11
}

TEST(PlotCanvasTest, ClipsToRectangleAndIgnoresFarOrNonFinitePoints) {
  PlotCanvas c(20, 20, kWhite);
  const PlotCanvas::Rect clip{5, 5, 5, 5};
  c.DrawLine(-1e12, 7, 1e12, 7, kRed, 1, &clip);  // clipped analytically, not walked
  EXPECT_EQ(CountColor(c, kRed), 5);
  for (int x = 5; x < 10; ++x) EXPECT_EQ(c.At(x, 7), kRed);
  c.DrawLine(0, 0, std::nan(""), 3, kRed, 1);
  EXPECT_EQ(CountColor(c, kRed), 5);
}

TEST(PlotCanvasTest, TextUsesTheFontGlyphs) {
  const int scale = 2;
  PlotCanvas c(40, 20, kWhite);
  c.DrawText(1, 1, "1", kRed, scale);
  int ink = 0;
  for (const auto row : BitmapFont::Glyph('1')) {
    for (int b = 0; b < BitmapFont::kGlyphWidth; ++b) ink += (row >> b) & 1;
  }
  EXPECT_EQ(CountColor(c, kRed), ink * scale * scale);
  // Top row of '1' is "..#..": pixel column 2 scaled.
  EXPECT_EQ(c.At(1 + 2 * scale, 1), kRed);
  EXPECT_EQ(c.At(1, 1), kWhite);
  EXPECT_EQ(PlotCanvas::TextWidth("abc", 1), 17);
  EXPECT_EQ(PlotCanvas::TextHeight(3), 21);
}

TEST(PlotCanvasTest, RejectsBadSizes) {
  EXPECT_THROW(PlotCanvas(0, 10, kWhite), InputError);
  EXPECT_THROW(PlotCanvas(10, 100000, kWhite), InputError);
}

TEST(BitmapFontTest, EveryDocumentedCharacterHasItsOwnGlyph) {
  const std::string chars = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.-+()[]/%:,_=";
  const auto& unknown = BitmapFont::Glyph('~');
  for (std::size_t i = 0; i < chars.size(); ++i) {
    EXPECT_NE(BitmapFont::Glyph(chars[i]), unknown) << chars[i];
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(BitmapFont::Glyph(chars[i]), BitmapFont::Glyph(chars[j])) << chars[i] << chars[j];
  }
  EXPECT_EQ(BitmapFont::Glyph('x'), BitmapFont::Glyph('X'));
}

}  // namespace
}  // namespace unimap::eval
