#include "io/PlyReader.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ScratchFolder;
using test::WriteText;

// value's bytes, most significant first when big_endian.
template <typename T>
std::string Bytes(T value, bool big_endian) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));  // the host (x86, ARM) is little-endian
  if (big_endian) bytes = std::string(bytes.rbegin(), bytes.rend());
  return bytes;
}

// Expects ReadPlyVertices(file) to throw InputError containing file and part.
void ExpectError(const std::filesystem::path& file, const std::string& part) {
  try {
    ReadPlyVertices(file);
    ADD_FAILURE() << "expected InputError containing '" << part << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

TEST(PlyReader, AsciiWithExtraPropertiesAndFaces) {
  ScratchFolder dir;
  WriteText(dir / "a.ply",
            "ply\r\nformat ascii 1.0\r\ncomment from another tool\r\nelement vertex 3\r\n"
            "property uchar red\r\nproperty double z\r\nproperty float y\r\nproperty int x\r\n"
            "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
            "255 0.5 -1.25 3\r\n0 1e-3 2 -4\r\n7 -0 0 0\r\n3 0 1 2\r\n");
  const std::vector<Eigen::Vector3f> points = ReadPlyVertices(dir / "a.ply");
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0], Eigen::Vector3f(3.0f, -1.25f, 0.5f));
  EXPECT_EQ(points[1], Eigen::Vector3f(-4.0f, 2.0f, 0.001f));
  EXPECT_EQ(points[2], Eigen::Vector3f(0.0f, 0.0f, 0.0f));
}

TEST(PlyReader, BinaryBothByteOrdersAndEveryScalarType) {
  ScratchFolder dir;
  for (const bool big : {false, true}) {
    std::string header = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                         " 1.0\nelement vertex 2\nproperty char a\nproperty uchar b\nproperty short c\n"
                         "property ushort d\nproperty int x\nproperty uint e\nproperty float y\n"
                         "property double z\nend_header\n";
    std::string data;
    const std::int32_t xs[2] = {-123456, 7};
    const float ys[2] = {0.1f, -3.5e30f};
    const double zs[2] = {-2.0e-300, 1.0 / 3.0};
    for (int v = 0; v < 2; ++v) {
      data += Bytes<std::int8_t>(-5, big) + Bytes<std::uint8_t>(200, big) + Bytes<std::int16_t>(-300, big) +
              Bytes<std::uint16_t>(60000, big) + Bytes(xs[v], big) + Bytes<std::uint32_t>(4000000000u, big) +
              Bytes(ys[v], big) + Bytes(zs[v], big);
    }
    WriteText(dir / "b.ply", header + data);
    const std::vector<Eigen::Vector3f> points = ReadPlyVertices(dir / "b.ply");
    ASSERT_EQ(points.size(), 2u) << "big endian " << big;
    for (std::size_t v = 0; v < 2; ++v) {
      EXPECT_EQ(points[v].x(), static_cast<float>(xs[v])) << "big endian " << big;
      EXPECT_EQ(points[v].y(), ys[v]) << "big endian " << big;
      EXPECT_EQ(points[v].z(), static_cast<float>(zs[v])) << "big endian " << big;
    }
  }
}

TEST(PlyReader, NonFiniteValuesAreKept) {
  ScratchFolder dir;
  WriteText(dir / "n.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nend_header\nnan inf 1\n");
  const std::vector<Eigen::Vector3f> points = ReadPlyVertices(dir / "n.ply");
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(std::isnan(points[0].x()));
  EXPECT_TRUE(std::isinf(points[0].y()));
}

TEST(PlyReader, BadFilesAreInputErrorsNamingTheFile) {
  ScratchFolder dir;
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const auto write = [&](const std::string& name, const std::string& text) {
    WriteText(dir / name, text);
    return dir / name;
  };
  ExpectError(dir / "missing.ply", "cannot open");
  ExpectError(write("not.ply", "pcd\n"), "not a PLY file");
  ExpectError(write("fmt.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 0\n" + xyz + "end_header\n"),
              "unsupported PLY format");
  ExpectError(write("noz.ply",
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "end_header\n1 2\n"),
              "no property z");
  ExpectError(write("face.ply",
                    "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int i\n"
                    "element vertex 1\n" +
                        xyz + "end_header\n"),
              "before the vertex element");
  ExpectError(
      write("list.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "property list uchar int i\nend_header\n"),
      "list property");
  ExpectError(write("count.ply", "ply\nformat ascii 1.0\nelement vertex -1\n" + xyz + "end_header\n"),
              "bad PLY vertex element");
  ExpectError(write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz), "no end_header");
  ExpectError(write("short.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2\n" + xyz + "end_header\n" +
                                     std::string(20, '\0')),
              "ends after 1 of 2 vertices");
  ExpectError(write("ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz + "end_header\n1 2 3\n4 five 6\n"),
              "ascii.ply: 9: expected 3 numbers");
}

}  // namespace
}  // namespace unimap::io
