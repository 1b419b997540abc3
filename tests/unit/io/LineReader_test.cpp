#include "io/LineReader.hpp"

#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

std::vector<std::string> AllLines(const std::filesystem::path& file) {
  LineReader reader(file);
  std::vector<std::string> lines;
  std::string_view line;
  while (reader.Next(&line)) {
    lines.emplace_back(line);
    EXPECT_EQ(reader.line_number(), static_cast<std::int64_t>(lines.size()));
  }
  return lines;
}

TEST(LineReader, HandlesCrLfBlankLinesAndALastLineWithoutEnd) {
  test::ScratchFolder folder;
  test::WriteText(folder / "a.txt", "one\r\n\ntwo\nthree");
  EXPECT_EQ(AllLines(folder / "a.txt"), (std::vector<std::string>{"one", "", "two", "three"}));
}

TEST(LineReader, EmptyFileHasNoLines) {
  test::ScratchFolder folder;
  test::WriteText(folder / "empty.txt", "");
  EXPECT_TRUE(AllLines(folder / "empty.txt").empty());
}

TEST(LineReader, LinesLongerThanTheReadChunkComeBackWhole) {
  test::ScratchFolder folder;
  std::string text;
  std::vector<std::string> expected;
  for (int i = 0; i < 40; ++i) {  // lines of up to ~200 kB straddle the 64 kB chunks
    expected.push_back(std::string(static_cast<std::size_t>(i) * 5000 + 1, static_cast<char>('a' + i % 26)));
    text += expected.back() + "\n";
  }
  test::WriteText(folder / "long.txt", text);
  EXPECT_EQ(AllLines(folder / "long.txt"), expected);
}

TEST(LineReader, RefusesAnOverlongLineNamingTheFileAndLine) {
  test::ScratchFolder folder;
  test::WriteText(folder / "bin.dat", "ok\n" + std::string(LineReader::kMaxLineBytes + 10, 'x'));
  LineReader reader(folder / "bin.dat");
  std::string_view line;
  ASSERT_TRUE(reader.Next(&line));
  try {
    reader.Next(&line);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bin.dat:2:"), std::string::npos) << e.what();
  }
}

TEST(LineReader, MissingFileIsAnInputError) {
  test::ScratchFolder folder;
  EXPECT_THROW(LineReader(folder / "missing.txt"), InputError);
}

}  // namespace
}  // namespace unimap::io
