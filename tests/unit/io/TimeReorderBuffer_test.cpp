#include "io/TimeReorderBuffer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace unimap::io {
namespace {

TEST(TimeReorderBufferTest, ReleasesInTimeOrderOnceTheWindowHasPassed) {
  TimeReorderBuffer<std::string> buffer(1.0);
  std::vector<std::string> out;
  auto drain = [&](bool flush) {
    while (auto item = buffer.Pop(flush)) out.push_back(*item);
  };
  EXPECT_TRUE(buffer.Push(10.0, "a"));
  EXPECT_TRUE(buffer.Push(10.6, "c"));
  drain(false);
  EXPECT_TRUE(out.empty());             // nothing is 1 s older than the newest (10.6) yet
  EXPECT_TRUE(buffer.Push(10.3, "b"));  // late, within the window
  EXPECT_TRUE(buffer.Push(11.5, "d"));
  drain(false);
  EXPECT_EQ(out, (std::vector<std::string>{"a", "b"}));  // 10.0 and 10.3 < 11.5 - 1
  EXPECT_EQ(buffer.size(), 2u);
  // Later than the window allows: 10.2 is before "b", already released.
  EXPECT_FALSE(buffer.Push(10.2, "late"));
  EXPECT_TRUE(buffer.Push(10.3, "tie"));  // equal to the last released time is still in order
  drain(true);
  EXPECT_EQ(out, (std::vector<std::string>{"a", "b", "tie", "c", "d"}));
  EXPECT_EQ(buffer.size(), 0u);
}

TEST(TimeReorderBufferTest, EqualTimesKeepArrivalOrder) {
  TimeReorderBuffer<int> buffer(0.0);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(buffer.Push(1.0, i));
  std::vector<int> out;
  while (auto item = buffer.Pop(true)) out.push_back(*item);
  EXPECT_EQ(out, (std::vector<int>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace unimap::io
