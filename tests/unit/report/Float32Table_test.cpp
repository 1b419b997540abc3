#include "report/Float32Table.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

namespace unimap::report {
namespace {

TEST(Float32TableTest, PacksLittleEndianFloat32AsBase64) {
  Float32Table table(2);
  table.AddRow({1.0, -2.0});  // 0x3f800000, 0xc0000000
  EXPECT_EQ(table.rows(), 1u);
  EXPECT_EQ(table.Base64(), "AACAPwAAAMA=");
  EXPECT_THROW(table.AddRow({1.0}), std::invalid_argument);
}

TEST(Float32TableTest, SampleKeepsEveryKthToFitTheBudget) {
  EXPECT_EQ(Float32Table::Sample(5, 10).size(), 5u);
  EXPECT_EQ(Float32Table::Sample(10, 10).size(), 10u);
  const std::vector<std::size_t> kept = Float32Table::Sample(25, 10);  // k = 3
  ASSERT_EQ(kept.size(), 9u);
  EXPECT_EQ(kept[1], 3u);
  EXPECT_EQ(kept.back(), 24u);
  EXPECT_LE(Float32Table::Sample(1000001, 250000).size(), 250000u);
  EXPECT_TRUE(Float32Table::Sample(0, 10).empty());
}

}  // namespace
}  // namespace unimap::report
