#include "eval/PngEncoder.hpp"

#include <gtest/gtest.h>

#include "PngTestSupport.hpp"

namespace unimap::eval {
namespace {

TEST(PngEncoderTest, WritesSignatureAndIhdrWithTheCanvasSize) {
  PlotCanvas canvas(123, 45, {10, 20, 30});
  canvas.DrawLine(0, 0, 122, 44, {255, 0, 0}, 2);
  const std::string png = EncodePng(canvas);
  ASSERT_TRUE(testing::HasPngSignatureAndIhdr(png));
  EXPECT_EQ(testing::PngWidth(png), 123u);
  EXPECT_EQ(testing::PngHeight(png), 45u);
  EXPECT_EQ(static_cast<unsigned char>(png[24]), 8u);  // bit depth
  EXPECT_EQ(static_cast<unsigned char>(png[25]), 2u);  // colour type: RGB
  EXPECT_EQ(png.compare(png.size() - 8, 4, "IEND"), 0);
}

}  // namespace
}  // namespace unimap::eval
