#include "io/PcdWriter.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/PcdPointLoader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ReadText;
using test::SameBits;
using test::ScratchFolder;

// Deterministic finite points: random bit patterns (subnormals, -0, huge
// values) mixed with ordinary coordinates.
std::vector<Eigen::Vector3f> FinitePoints(std::size_t n, std::uint32_t seed) {
  test::ValueSource values(seed);
  std::vector<Eigen::Vector3f> points;
  while (points.size() < n) {
    Eigen::Vector3f p;
    for (int j = 0; j < 3; ++j) {
      p[j] = points.size() % 2 == 0 ? values.AnyFloat() : static_cast<float>(values.Uniform(-120.0, 120.0));
    }
    if (p.allFinite()) points.push_back(p);
  }
  points.push_back(Eigen::Vector3f(0.0f, -0.0f, std::numeric_limits<float>::denorm_min()));
  points.push_back(Eigen::Vector3f(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(), 0.1f));
  return points;
}

std::string ExpectedHeader(std::size_t n, const std::string& data) {
  const std::string count = std::to_string(n);
  return "# .PCD v0.7 - Point Cloud Data file format (written by unimap)\nVERSION 0.7\nFIELDS x y z\n"
         "SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " +
         count +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
         "POINTS " +
         count + "\nDATA " + data + "\n";
}

// The points of a binary file written by WritePcdXyz, parsed by hand
// (little-endian float32 after the header).
std::vector<Eigen::Vector3f> ParseBinary(const std::string& bytes, std::size_t header_size) {
  std::vector<Eigen::Vector3f> points;
  for (std::size_t at = header_size; at + 12 <= bytes.size(); at += 12) {
    Eigen::Vector3f p;
    for (int j = 0; j < 3; ++j) {
      std::uint32_t bits = 0;
      for (int b = 0; b < 4; ++b) {
        bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 4 * j + b])) << (8 * b);
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

TEST(PcdWriter, BinaryHeaderAndLittleEndianDataAreExact) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = FinitePoints(500, 7);
  WritePcdXyz(dir / "cloud.pcd", points);
  const std::string bytes = ReadText(dir / "cloud.pcd");
  const std::string header = ExpectedHeader(points.size(), "binary");
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(bytes.size(), header.size() + 12 * points.size());
  ExpectSamePoints(points, ParseBinary(bytes, header.size()));
  EXPECT_FALSE(std::filesystem::exists(dir / "cloud.pcd.partial"));
}

TEST(PcdWriter, AsciiIsOneShortestRoundTripLinePerPoint) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = {{1.5f, -0.25f, 3.0f}, {0.1f, 1e-30f, -7e20f}};
  WritePcdXyz(dir / "cloud.pcd", points, PcdEncoding::kAscii);
  EXPECT_EQ(ReadText(dir / "cloud.pcd"), ExpectedHeader(2, "ascii") + "1.5 -0.25 3\n0.1 1e-30 -7e+20\n");
}

TEST(PcdWriter, IntensitiesAreAFourthField) {
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = {{1.5f, -0.25f, 3.0f}, {0.1f, 1e-30f, -7e20f}};
  const std::vector<float> intensities = {0.5f, 252.45f};
  WritePcdXyz(dir / "cloud.pcd", points, PcdEncoding::kAscii, &intensities);
  std::string header = ExpectedHeader(2, "ascii");
  const auto replace = [&header](const std::string& from, const std::string& to) {
    header.replace(header.find(from), from.size(), to);
  };
  replace("FIELDS x y z\n", "FIELDS x y z intensity\n");
  replace("SIZE 4 4 4\n", "SIZE 4 4 4 4\n");
  replace("TYPE F F F\n", "TYPE F F F F\n");
  replace("COUNT 1 1 1\n", "COUNT 1 1 1 1\n");
  EXPECT_EQ(ReadText(dir / "cloud.pcd"), header + "1.5 -0.25 3 0.5\n0.1 1e-30 -7e+20 252.45\n");
  WritePcdXyz(dir / "cloud.pcd", points, PcdEncoding::kBinary, &intensities);
  const std::string bytes = ReadText(dir / "cloud.pcd");
  EXPECT_EQ(bytes.size(), bytes.find("DATA binary\n") + 12 + 2 * 16) << "16 bytes per point";
  const std::vector<float> one = {1.0f};
  EXPECT_THROW(WritePcdXyz(dir / "other.pcd", points, PcdEncoding::kBinary, &one), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "other.pcd"));
}

TEST(PcdWriter, NonFinitePointsAreWrittenAsTheyAre) {
  ScratchFolder dir;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<Eigen::Vector3f> points = {{nan, 1.0f, 2.0f}, {-inf, inf, 0.5f}};
  WritePcdXyz(dir / "cloud.pcd", points);
  const std::string bytes = ReadText(dir / "cloud.pcd");
  ExpectSamePoints(points, ParseBinary(bytes, ExpectedHeader(2, "binary").size()));
  WritePcdXyz(dir / "cloud_ascii.pcd", points, PcdEncoding::kAscii);
  EXPECT_EQ(ReadText(dir / "cloud_ascii.pcd"), ExpectedHeader(2, "ascii") + "nan 1 2\n-inf inf 0.5\n");
}

TEST(PcdWriter, EmptyCloudIsAHeaderOnly) {
  ScratchFolder dir;
  WritePcdXyz(dir / "empty.pcd", {});
  EXPECT_EQ(ReadText(dir / "empty.pcd"), ExpectedHeader(0, "binary"));
}

TEST(PcdWriter, UnwritableFileThrowsNamingItAndLeavesNoFile) {
  ScratchFolder dir;
  const std::filesystem::path file = dir / "no_such_folder" / "cloud.pcd";
  try {
    WritePcdXyz(file, {{1.0f, 2.0f, 3.0f}});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(PcdWriter, RoundTripsThroughPcdPointLoaderBitExactly) {
  if (!PcdSupported()) {
    GTEST_SKIP() << "this build has no PCL: the header and data are checked by hand above";
  }
  ScratchFolder dir;
  const std::vector<Eigen::Vector3f> points = FinitePoints(2000, 11);
  for (const PcdEncoding encoding : {PcdEncoding::kBinary, PcdEncoding::kAscii}) {
    const std::filesystem::path file = dir / (encoding == PcdEncoding::kBinary ? "b.pcd" : "a.pcd");
    WritePcdXyz(file, points, encoding);
    std::vector<Eigen::Vector4f> xyzi;
    LoadPcdXyzi(file, &xyzi);
    std::vector<Eigen::Vector3f> read;
    for (const Eigen::Vector4f& p : xyzi) {
      read.push_back(p.head<3>());
      EXPECT_EQ(p[3], 0.0f);  // no intensity field: 0
    }
    ExpectSamePoints(points, read);
  }
}

}  // namespace
}  // namespace unimap::io
