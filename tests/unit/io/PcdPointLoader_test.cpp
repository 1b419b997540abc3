#include "io/PcdPointLoader.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/PcdHeader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ScratchFolder;

// A header without a COUNT line (counts default to 1).
std::string PlainHeader(const std::string& fields, const std::string& size, const std::string& type,
                        std::uint64_t points, const std::string& data) {
  return "VERSION 0.7\nFIELDS " + fields + "\nSIZE " + size + "\nTYPE " + type + "\nWIDTH " + std::to_string(points) +
         "\nHEIGHT 1\nPOINTS " + std::to_string(points) + "\nDATA " + data + "\n";
}

// The InputError message of loading file (a failure if it loads).
std::string LoadError(const std::filesystem::path& file) {
  std::vector<Eigen::Vector4f> xyzi;
  try {
    LoadPcdXyzi(file, &xyzi);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << file;
  return {};
}

::testing::AssertionResult Has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" lacks \"" << part << "\"";
}

TEST(PcdPointLoader, AsciiPointsWithAndWithoutIntensity) {
  ScratchFolder folder;
  test::WriteText(folder / "a.pcd",
                  PlainHeader("x y z intensity", "4 4 4 4", "F F F F", 2, "ascii") + "1 2 3 0.5\n-1e3 nan 4 7\n");
  std::vector<Eigen::Vector4f> xyzi;
  LoadPcdXyzi(folder / "a.pcd", &xyzi);
  ASSERT_EQ(xyzi.size(), 2u);
  EXPECT_EQ(xyzi[0], Eigen::Vector4f(1, 2, 3, 0.5f));
  EXPECT_EQ(xyzi[1].x(), -1000.0f);
  EXPECT_TRUE(std::isnan(xyzi[1].y()));  // kept: the caller decides
  test::WriteText(folder / "b.pcd", PlainHeader("x y z", "4 4 4", "F F F", 1, "ascii") + "\n1 2 3\n\n");
  LoadPcdXyzi(folder / "b.pcd", &xyzi);
  ASSERT_EQ(xyzi.size(), 1u);
  EXPECT_EQ(xyzi[0], Eigen::Vector4f(1, 2, 3, 0));
}

TEST(PcdPointLoader, AsciiTextLineNamesItsLine) {
  ScratchFolder folder;
  // Line 9 (after the 8 header lines) holds a word: before, PCL read it as a point at the origin.
  test::WriteText(folder / "t.pcd", PlainHeader("x y z", "4 4 4", "F F F", 2, "ascii") + "1 2 3\nhello world again\n");
  EXPECT_TRUE(Has(LoadError(folder / "t.pcd"), "t.pcd:10: value 1 'hello' is not a number"));
  test::WriteText(folder / "s.pcd", PlainHeader("x y z", "4 4 4", "F F F", 1, "ascii") + "1 2\n");
  EXPECT_TRUE(Has(LoadError(folder / "s.pcd"), "s.pcd:9: a point needs 3 values, found 2"));
  test::WriteText(folder / "l.pcd", PlainHeader("x y z", "4 4 4", "F F F", 1, "ascii") + "1 2 3 4\n");
  EXPECT_TRUE(Has(LoadError(folder / "l.pcd"), "l.pcd:9: a point needs 3 values, found more"));
}

TEST(PcdPointLoader, AsciiPointCountMustMatchTheHeader) {
  ScratchFolder folder;
  test::WriteText(folder / "few.pcd", PlainHeader("x y z", "4 4 4", "F F F", 3, "ascii") + "1 2 3\n4 5 6\n");
  EXPECT_TRUE(Has(LoadError(folder / "few.pcd"), "the data ends after 2 of the 3 points"));
  test::WriteText(folder / "many.pcd", PlainHeader("x y z", "4 4 4", "F F F", 1, "ascii") + "1 2 3\n4 5 6\n");
  EXPECT_TRUE(Has(LoadError(folder / "many.pcd"), "many.pcd:10: more points than the 1 the header announces"));
}

TEST(PcdPointLoader, HugePointCountsAreRefusedBeforeAllocating) {
  ScratchFolder folder;
  // 2^31 - 1 points of 16 bytes in a file of a few hundred bytes: PCL allocated 32 GiB and threw bad_alloc.
  test::WriteText(folder / "huge.pcd",
                  PlainHeader("x y z intensity", "4 4 4 4", "F F F F", 2147483647, "binary") + std::string(64, '\0'));
  EXPECT_TRUE(Has(LoadError(folder / "huge.pcd"),
                  "the header announces 2147483647 points of 16 bytes (34359738352 bytes), only 64 bytes follow"));
  test::WriteText(folder / "ascii.pcd", PlainHeader("x y z", "4 4 4", "F F F", 300000000, "ascii") + "1 2 3\n");
  EXPECT_TRUE(Has(LoadError(folder / "ascii.pcd"), "the header announces 300000000 points, the 6 bytes of ascii"));
  // binary_compressed: the block must be present and able to expand to the points announced.
  std::string sizes(8, '\0');
  const std::uint32_t compressed = 10, uncompressed = 12 * 1000;
  std::memcpy(&sizes[0], &compressed, 4);
  std::memcpy(&sizes[4], &uncompressed, 4);
  test::WriteText(folder / "lzf.pcd",
                  PlainHeader("x y z", "4 4 4", "F F F", 1000, "binary_compressed") + sizes + std::string(10, 'x'));
  EXPECT_TRUE(Has(LoadError(folder / "lzf.pcd"), "more than a 10-byte LZF block can expand to"));
  test::WriteText(folder / "cut.pcd",
                  PlainHeader("x y z", "4 4 4", "F F F", 1000, "binary_compressed") + sizes + std::string(4, 'x'));
  EXPECT_TRUE(Has(LoadError(folder / "cut.pcd"), "compressed block of 10 bytes, only 4 bytes follow"));
}

TEST(PcdPointLoader, BinaryFieldsOfAnyTypeAndOrder) {
  ScratchFolder folder;
  std::string body;
  const auto put = [&body](const auto& value) { body.append(reinterpret_cast<const char*>(&value), sizeof(value)); };
  for (int i = 0; i < 3; ++i) {
    put(std::uint8_t{7});                      // rgb-like byte before x
    put(static_cast<double>(i) + 0.25);        // x: F8
    put(static_cast<float>(-i));               // y: F4
    put(static_cast<std::int16_t>(-300 * i));  // z: I2
    put(static_cast<float>(10 * i));           // intensity
  }
  test::WriteText(folder / "b.pcd", PlainHeader("c x y z intensity", "1 8 4 2 4", "U F F I F", 3, "binary") + body);
  std::vector<Eigen::Vector4f> xyzi;
  LoadPcdXyzi(folder / "b.pcd", &xyzi);
  ASSERT_EQ(xyzi.size(), 3u);
  EXPECT_EQ(xyzi[2], Eigen::Vector4f(2.25f, -2.0f, -600.0f, 20.0f));
}

TEST(PcdPointLoader, MalformedHeadersNameTheLine) {
  ScratchFolder folder;
  const auto header_error = [&folder](const std::string& text) {
    test::WriteText(folder / "h.pcd", text);
    return LoadError(folder / "h.pcd");
  };
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4\n"), "h.pcd:2: SIZE has 2 entries for 3 fields"));
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4 3\n"), "h.pcd:2: SIZE of field z is 3"));
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\n"), "h.pcd:3: TYPE of field z is 'Q'"));
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 3\nDATA ascii\n"),
                  "h.pcd:7: POINTS 3 is not WIDTH x HEIGHT = 2"));
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nDATA zip\n"), "h.pcd:5: DATA 'zip'"));
  EXPECT_TRUE(
      Has(header_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\n"), "the header ends without a DATA line"));
  EXPECT_TRUE(Has(header_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH -1\nDATA ascii\n"),
                  "h.pcd:4: WIDTH '-1' is not a whole number"));
  EXPECT_TRUE(Has(header_error("hello\n"), "h.pcd:1: unknown header line 'hello'"));
  EXPECT_TRUE(Has(header_error(std::string(70000, 'x')), "no DATA line within the first 65536 bytes"));
  EXPECT_TRUE(Has(header_error(PlainHeader("x y", "4 4", "F F", 0, "ascii")), "PCD file has no z field"));
}

}  // namespace
}  // namespace unimap::io
