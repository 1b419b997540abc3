#include "io/NumberText.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

namespace unimap::io {
namespace {

TEST(NumberText, EveryDoubleReadsBackBitExactly) {
  test::ValueSource values(7);
  for (int i = 0; i < 20000; ++i) {
    const double value = values.Any();
    std::string text;
    AppendNumber(&text, value);
    double back = 1.0;
    ASSERT_TRUE(ParseNumber(text, &back)) << text;
    ASSERT_TRUE(test::SameBits(value, back)) << text;
  }
}

TEST(NumberText, WritesShortestTextAndKeepsSigns) {
  std::string text;
  AppendNumber(&text, 0.1);
  text += ' ';
  AppendNumber(&text, -0.0);
  text += ' ';
  AppendNumber(&text, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(text, "0.1 -0 5e-324");
}

TEST(NumberText, ParsesPlusSignsExponentsAndNonFinite) {
  double v = 0.0;
  EXPECT_TRUE(ParseNumber("+1.5e+09", &v));
  EXPECT_EQ(v, 1.5e9);
  EXPECT_TRUE(ParseNumber("-0", &v));
  EXPECT_TRUE(std::signbit(v));
  EXPECT_TRUE(ParseNumber("inf", &v));
  EXPECT_TRUE(std::isinf(v));
  EXPECT_TRUE(ParseNumber("-nan", &v));
  EXPECT_TRUE(std::isnan(v));
}

TEST(NumberText, RejectsAnythingThatIsNotEntirelyANumber) {
  double v = 0.0;
  for (const char* bad : {"", "+", "-", "1.5x", "1,5", "0x10", "+-1", "++1", "1e400", " 1", "abc"}) {
    EXPECT_FALSE(ParseNumber(bad, &v)) << "'" << bad << "'";
  }
}

}  // namespace
}  // namespace unimap::io
