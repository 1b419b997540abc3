#include "io/PlyWriter.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/PlyReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ReadText;
using test::SameBits;
using test::ScratchFolder;

const std::string kHeaderStart = "ply\nformat binary_little_endian 1.0\ncomment written by unimap\nelement vertex ";
const std::string kHeaderEnd = "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";

// Finite points with extreme values (subnormals, -0, float max) and ordinary ones.
std::vector<Eigen::Vector3f> FinitePoints(std::size_t n, std::uint32_t seed) {
  test::ValueSource values(seed);
  std::vector<Eigen::Vector3f> points;
  while (points.size() < n) {
    Eigen::Vector3f p;
    for (int j = 0; j < 3; ++j) {
      p[j] = points.size() % 2 == 0 ? values.AnyFloat() : static_cast<float>(values.Uniform(-80.0, 80.0));
    }
    if (p.allFinite()) points.push_back(p);
  }
  points.push_back(Eigen::Vector3f(0.0f, -0.0f, std::numeric_limits<float>::denorm_min()));
  points.push_back(Eigen::Vector3f(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(), 0.1f));
  return points;
}

// A minimal reader of exactly the layout WritePly documents, independent of
// io::ReadPlyVertices: checks the header text, then decodes little-endian
// float32 triples by hand. Fails the test on any deviation.
std::vector<Eigen::Vector3f> ParseOurPly(const std::string& bytes) {
  std::vector<Eigen::Vector3f> points;
  EXPECT_EQ(bytes.compare(0, kHeaderStart.size(), kHeaderStart), 0);
  const std::size_t count_end = bytes.find('\n', kHeaderStart.size());
  const std::size_t n = std::stoul(bytes.substr(kHeaderStart.size(), count_end - kHeaderStart.size()));
  EXPECT_EQ(bytes.compare(count_end, kHeaderEnd.size(), kHeaderEnd), 0);
  const std::size_t data = count_end + kHeaderEnd.size();
  EXPECT_EQ(bytes.size(), data + 12 * n) << "exactly 12 bytes per point after the header";
  for (std::size_t at = data; at + 12 <= bytes.size(); at += 12) {
    Eigen::Vector3f p;
    for (int j = 0; j < 3; ++j) {
      std::uint32_t bits = 0;
      for (std::size_t b = 0; b < 4; ++b) {
        bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 4 * static_cast<std::size_t>(j) + b]))
                << (8 * b);
      }
      std::memcpy(&p[j], &bits, sizeof(float));
    }
    points.push_back(p);
  }
  return points;
}

void ExpectSamePoints(const std::vector<Eigen::Vector3f>& expected, const std::vector<Eigen::Vector3f>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    for (int j = 0; j < 3; ++j) {
      ASSERT_TRUE(SameBits(expected[i][j], actual[i][j]))
          << "point " << i << " axis " << j << ": " << expected[i][j] << " vs " << actual[i][j];
    }
  }
}

TEST(PlyWriter, HeaderAndLittleEndianFloatsAreExact) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = FinitePoints(10000, 3);  // more than one 4096-point chunk
  WritePly(dir / "map.ply", points);
  const std::string bytes = ReadText(dir / "map.ply");
  ASSERT_EQ(bytes.substr(0, kHeaderStart.size() + 5), kHeaderStart + "10002");
  ExpectSamePoints(points, ParseOurPly(bytes));
  EXPECT_FALSE(std::filesystem::exists(dir / "map.ply.partial"));
}

TEST(PlyWriter, KnownBytesOfOnePoint) {
  ScratchFolder dir;
  WritePly(dir / "one.ply", {Eigen::Vector3f(1.0f, -2.0f, 0.5f)});
  const std::string bytes = ReadText(dir / "one.ply");
  const std::string header = kHeaderStart + "1" + kHeaderEnd;
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  // 1.0f = 0x3F800000, -2.0f = 0xC0000000, 0.5f = 0x3F000000, low byte first.
  const std::string data("\x00\x00\x80\x3F\x00\x00\x00\xC0\x00\x00\x00\x3F", 12);
  EXPECT_EQ(bytes.substr(header.size()), data);
}

TEST(PlyWriter, IntensitiesAreAFourthPropertyAndReadBack) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = FinitePoints(5000, 4);
  std::vector<float> intensities;
  for (std::size_t i = 0; i < points.size(); ++i) intensities.push_back(0.25f * static_cast<float>(i));
  WritePly(dir / "map.ply", points, &intensities);
  const std::string bytes = ReadText(dir / "map.ply");
  const std::string end = "property float z\nproperty float intensity\nend_header\n";
  const std::size_t data = bytes.find(end) + end.size();
  ASSERT_NE(bytes.find(end), std::string::npos);
  ASSERT_EQ(bytes.size(), data + 16 * points.size());
  float last = 0.0f;
  std::memcpy(&last, &bytes[data + 16 * (points.size() - 1) + 12], sizeof(float));
  EXPECT_EQ(last, intensities.back());
  ExpectSamePoints(points, ReadPlyVertices(dir / "map.ply"));  // a reader by the header skips the extra property
  const std::vector<float> too_few = {1.0f};
  EXPECT_THROW(WritePly(dir / "bad.ply", points, &too_few), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.ply"));
}

TEST(PlyWriter, EmptyCloudIsAValidFile) {
  ScratchFolder dir;
  WritePly(dir / "empty.ply", {});
  EXPECT_EQ(ReadText(dir / "empty.ply"), kHeaderStart + "0" + kHeaderEnd);
  EXPECT_TRUE(ReadPlyVertices(dir / "empty.ply").empty());
}

TEST(PlyWriter, ReadsBackThroughPlyReader) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = FinitePoints(500, 11);
  WritePly(dir / "map.ply", points);
  ExpectSamePoints(points, ReadPlyVertices(dir / "map.ply"));
}

TEST(PlyWriter, NonFinitePointIsRejectedAndLeavesNoFile) {
  ScratchFolder dir;
  std::vector<Eigen::Vector3f> points = FinitePoints(20, 5);
  points[7].y() = std::numeric_limits<float>::quiet_NaN();
  const std::filesystem::path file = dir / "bad.ply";
  try {
    WritePly(file, points);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point 7 is not finite"), std::string::npos) << e.what();
  }
  points[7].y() = 0.0f;
  points[19].z() = -std::numeric_limits<float>::infinity();
  EXPECT_THROW(WritePly(file, points), InputError);
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.ply.partial"));
}

TEST(PlyWriter, UnwritableFolderIsAnInputErrorNamingTheFile) {
  ScratchFolder dir;
  const std::filesystem::path file = dir / "no_such_folder" / "map.ply";
  try {
    WritePly(file, FinitePoints(3, 1));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST(PlyWriter, ReplacesAnExistingFileWhole) {
  ScratchFolder dir;
  WritePly(dir / "map.ply", FinitePoints(100, 2));
  const std::vector<Eigen::Vector3f> second = FinitePoints(4, 9);
  WritePly(dir / "map.ply", second);
  ExpectSamePoints(second, ParseOurPly(ReadText(dir / "map.ply")));
}

}  // namespace
}  // namespace unimap::io
