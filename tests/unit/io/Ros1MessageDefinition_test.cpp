#include "io/Ros1MessageDefinition.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// The tilting stand's custom message as its bag carries it (comments and
// all): a LaserScan, then the stepper's angle.
const char* kLaserScanAngle =
    "sensor_msgs/LaserScan laserScan\n"
    "float64 stepAngle\n"
    "================================================================================\n"
    "MSG: sensor_msgs/LaserScan\n"
    "# Single scan from a planar laser range-finder\n"
    "Header header            # timestamp in the header is the acquisition time of\n"
    "float32 angle_min        # start angle of the scan [rad]\n"
    "float32 angle_max\n"
    "float32 angle_increment\n"
    "float32 time_increment\n"
    "float32 scan_time\n"
    "float32 range_min\n"
    "float32 range_max\n"
    "float32[] ranges         # range data [m]\n"
    "float32[] intensities\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "uint32 seq\n"
    "time stamp\n"
    "string frame_id\n";

// Little-endian serialization helpers (ROS 1 wire format).
template <typename T>
void Put(std::vector<std::uint8_t>* out, T value) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
  out->insert(out->end(), bytes, bytes + sizeof(T));
}
void PutString(std::vector<std::uint8_t>* out, const std::string& s) {
  Put<std::uint32_t>(out, static_cast<std::uint32_t>(s.size()));
  out->insert(out->end(), s.begin(), s.end());
}

// One LaserScanAngle: seq 7, stamp 100 s + 250 ms, frame "laser", 3 ranges,
// no intensities, stepAngle 12.5 deg.
std::vector<std::uint8_t> Message() {
  std::vector<std::uint8_t> m;
  Put<std::uint32_t>(&m, 7);
  Put<std::uint32_t>(&m, 100);
  Put<std::uint32_t>(&m, 250000000);
  PutString(&m, "laser");
  for (float f : {-2.0f, 2.0f, 0.01f, 1e-4f, 0.1f, 0.02f, 5.6f}) Put<float>(&m, f);
  Put<std::uint32_t>(&m, 3);
  for (float f : {1.0f, 2.0f, 3.0f}) Put<float>(&m, f);
  Put<std::uint32_t>(&m, 0);
  Put<double>(&m, 12.5);
  return m;
}

TEST(Ros1MessageDefinition, FindsTheLaserScanAndTheAngleInACustomMessage) {
  const Ros1MessageDefinition d("pcg_node/LaserScanAngle", kLaserScanAngle);
  EXPECT_EQ(d.FieldsOfType("sensor_msgs/LaserScan"), std::vector<std::string>{"laserScan"});
  EXPECT_EQ(d.TypeOf("stepAngle"), "float64");
  EXPECT_EQ(d.TypeOf("laserScan.header"), "std_msgs/Header");  // "Header" resolves to std_msgs
  EXPECT_EQ(d.TypeOf("laserScan.ranges"), "float32[]");
  EXPECT_EQ(d.TypeOf("laserScan.nothing"), "");

  const std::vector<std::uint8_t> m = Message();
  // The scan: 4 + 8 + (4 + 5) header, 7 floats, 4 + 12 ranges, 4 intensities = 69 bytes.
  const Ros1MessageDefinition::Span scan = d.Locate(m.data(), m.size(), "laserScan");
  EXPECT_EQ(scan.offset, 0u);
  EXPECT_EQ(scan.length, 69u);
  const Ros1MessageDefinition::Span angle = d.Locate(m.data(), m.size(), "stepAngle");
  EXPECT_EQ(angle.offset, 69u);
  EXPECT_EQ(angle.length, 8u);
  EXPECT_DOUBLE_EQ(d.ReadNumber(m.data(), m.size(), "stepAngle"), 12.5);
  EXPECT_DOUBLE_EQ(d.ReadNumber(m.data(), m.size(), "laserScan.header.seq"), 7.0);
  EXPECT_FLOAT_EQ(static_cast<float>(d.ReadNumber(m.data(), m.size(), "laserScan.range_max")), 5.6f);
  EXPECT_EQ(d.Locate(m.data(), m.size(), "laserScan.header.frame_id").length, 9u);
}

TEST(Ros1MessageDefinition, TruncatedMessagesAndMissingFieldsAreInputErrors) {
  const Ros1MessageDefinition d("pcg_node/LaserScanAngle", kLaserScanAngle);
  std::vector<std::uint8_t> m = Message();
  m.resize(m.size() - 1);  // the angle's last byte missing
  EXPECT_THROW(d.ReadNumber(m.data(), m.size(), "stepAngle"), InputError);
  std::vector<std::uint8_t> huge = Message();
  const std::uint32_t count = 0xFFFFFFF0u;  // a range count far beyond the bytes present
  std::memcpy(huge.data() + 4 + 8 + 9 + 28, &count, 4);
  EXPECT_THROW(d.Locate(huge.data(), huge.size(), "stepAngle"), InputError);
  const std::vector<std::uint8_t> ok = Message();
  EXPECT_THROW(d.Locate(ok.data(), ok.size(), "tiltAngle"), InputError);
  EXPECT_THROW(d.ReadNumber(ok.data(), ok.size(), "laserScan.header.frame_id"), InputError);  // not a number
}

TEST(Ros1MessageDefinition, ConstantsFixedArraysAndNestedArraysAreLaidOutAsROSDoes) {
  const char* text =
      "uint8 MODE_A=1\n"
      "string NAME = x # a constant, not serialized\n"
      "int16[3] fixed\n"
      "Point[] points\n"
      "float32 after\n"
      "================================================================================\n"
      "MSG: geometry_msgs/Point\n"
      "float64 x\nfloat64 y\nfloat64 z\n";
  const Ros1MessageDefinition d("geometry_msgs/Polygonish", text);
  std::vector<std::uint8_t> m;
  for (const std::int16_t v : {std::int16_t{1}, std::int16_t{-2}, std::int16_t{3}}) Put<std::int16_t>(&m, v);
  Put<std::uint32_t>(&m, 2);
  for (double v : {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}) Put<double>(&m, v);
  Put<float>(&m, -0.5f);
  EXPECT_EQ(d.Locate(m.data(), m.size(), "fixed").length, 6u);
  EXPECT_EQ(d.Locate(m.data(), m.size(), "points").length, 4u + 48u);
  EXPECT_DOUBLE_EQ(d.ReadNumber(m.data(), m.size(), "after"), -0.5);
  EXPECT_TRUE(d.FieldsOfType("geometry_msgs/Point").empty());  // arrays are not searched
}

TEST(Ros1MessageDefinition, UndefinedTypesAndSelfContainingTypesAreErrors) {
  EXPECT_THROW(Ros1MessageDefinition("a/B", "sensor_msgs/LaserScan scan\n"), InputError);  // not defined
  EXPECT_THROW(Ros1MessageDefinition("a/B", "float64[x] bad\n"), InputError);
  EXPECT_THROW(Ros1MessageDefinition("a/B", "justonetoken\n"), InputError);
  EXPECT_THROW(Ros1MessageDefinition("a/B", "B inner\n"), InputError);  // a/B holds an a/B
  // Held through an array it is a tree, and legal: children[] may be empty.
  const Ros1MessageDefinition tree("a/Node", "float64 value\nNode[] children\n");
  std::vector<std::uint8_t> leaf;
  Put<double>(&leaf, 2.5);
  Put<std::uint32_t>(&leaf, 0);
  EXPECT_DOUBLE_EQ(tree.ReadNumber(leaf.data(), leaf.size(), "value"), 2.5);
  // An array claiming more elements than bytes left is a truncation, not a long loop.
  std::vector<std::uint8_t> lying = leaf;
  const std::uint32_t many = 0xFFFFFFFFu;
  std::memcpy(lying.data() + 8, &many, 4);
  EXPECT_THROW(tree.Locate(lying.data(), lying.size(), "children"), InputError);
  // Two of the next type, 30 deep: 2^30 fields from a 1 KB text (the fuzzer's out-of-memory).
  std::string wide = "T0 a\nT0 b\n";
  for (int k = 0; k < 30; ++k) {
    wide += "================================================================================\nMSG: x/T" +
            std::to_string(k) + "\nT" + std::to_string(k + 1) + " a\nT" + std::to_string(k + 1) + " b\n";
  }
  wide += "================================================================================\nMSG: x/T30\nfloat64 v\n";
  EXPECT_THROW(Ros1MessageDefinition("x/Wide", wide), InputError);
}

}  // namespace
}  // namespace unimap::io
