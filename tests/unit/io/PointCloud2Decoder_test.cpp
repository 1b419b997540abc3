#include "io/PointCloud2Decoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::uint8_t kUint8 = 2, kUint16 = 4, kUint32 = 6, kFloat32 = 7, kFloat64 = 8;

// Builds point records field by field (little-endian host, optional byte swap).
class CloudBuilder {
 public:
  CloudBuilder(std::uint32_t point_step, bool big_endian) : step_(point_step), big_endian_(big_endian) {}
  void NewPoint() { data_.resize(data_.size() + step_, 0); }
  template <typename T>
  void Put(std::uint32_t offset, T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    unsigned char* at = data_.data() + data_.size() - step_ + offset;
    for (std::size_t i = 0; i < sizeof(T); ++i) at[i] = big_endian_ ? bytes[sizeof(T) - 1 - i] : bytes[i];
  }
  const std::vector<std::uint8_t>& data() const { return data_; }
  std::uint32_t points() const { return static_cast<std::uint32_t>(data_.size() / step_); }

 private:
  std::uint32_t step_;
  bool big_endian_;
  std::vector<std::uint8_t> data_;
};

const std::vector<CloudField> kXyz = {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}};

std::vector<CloudField> With(std::vector<CloudField> extra) {
  std::vector<CloudField> fields = kXyz;
  fields.insert(fields.end(), extra.begin(), extra.end());
  return fields;
}

TEST(PointCloud2DecoderTest, SecondsAndNanosecondsFieldsGiveAbsoluteTimesAndRings) {
  // The layout of the Luminar clouds in the real bag.
  const auto fields = With({{"intensity", 16, kFloat32, 1},
                            {"time_sec", 20, kUint32, 1},
                            {"time_nsec", 24, kUint32, 1},
                            {"laser_id", 28, kUint16, 1}});
  CloudBuilder cloud(32, false);
  const std::uint32_t secs[2] = {1583971569u, 1583971570u};
  const std::uint32_t nsecs[2] = {927540000u, 15299642u};
  for (int i = 0; i < 2; ++i) {
    cloud.NewPoint();
    cloud.Put(0, 1.0f + static_cast<float>(i));
    cloud.Put(4, -2.0f);
    cloud.Put(8, 0.5f);
    cloud.Put(16, 7.0f);
    cloud.Put(20, secs[i]);
    cloud.Put(24, nsecs[i]);
    cloud.Put(28, static_cast<std::uint16_t>(i));
  }
  const PointCloud2Decoder decoder(fields, 32, false);
  const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 2, 1, 64, 1583971570.0153);
  EXPECT_EQ(out.time_convention, PointTimeConvention::kSecondsAndNanoseconds);
  ASSERT_EQ(out.scan.points.size(), 2u);
  EXPECT_TRUE(out.scan.has_point_time);
  EXPECT_DOUBLE_EQ(out.scan.points[0].time_s, 1583971569.0 + 0.92754);
  EXPECT_DOUBLE_EQ(out.scan.start_time_s, out.scan.points[0].time_s);
  EXPECT_DOUBLE_EQ(out.scan.end_time_s, 1583971570.0 + 0.015299642);
  EXPECT_EQ(out.scan.points[1].ring, 1);
  EXPECT_EQ(out.scan.points[1].position_m, Eigen::Vector3d(2.0, -2.0, 0.5));
  EXPECT_FLOAT_EQ(out.scan.points[0].intensity, 7.0f);
}

TEST(PointCloud2DecoderTest, RelativeTimeConventions) {
  const double stamp = 1000.0;
  // Velodyne: float32 "time", seconds after the stamp.
  {
    CloudBuilder cloud(16, false);
    cloud.NewPoint();
    cloud.Put(12, 0.025f);
    const PointCloud2Decoder decoder(With({{"time", 12, kFloat32, 1}}), 16, false);
    const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 1, 1, 16, stamp);
    EXPECT_EQ(out.time_convention, PointTimeConvention::kRelativeSeconds);
    EXPECT_DOUBLE_EQ(out.scan.points[0].time_s, stamp + static_cast<double>(0.025f));
  }
  // Ouster: uint32 "t", nanoseconds after the stamp; ring as uint8.
  {
    CloudBuilder cloud(20, false);
    cloud.NewPoint();
    cloud.Put(12, 50000000u);
    cloud.Put(16, static_cast<std::uint8_t>(63));
    const PointCloud2Decoder decoder(With({{"t", 12, kUint32, 1}, {"ring", 16, kUint8, 1}}), 20, false);
    const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 1, 1, 20, stamp);
    EXPECT_EQ(out.time_convention, PointTimeConvention::kRelativeNanoseconds);
    EXPECT_DOUBLE_EQ(out.scan.points[0].time_s, stamp + 0.05);
    EXPECT_EQ(out.scan.points[0].ring, 63);
  }
  // Hesai: float64 "timestamp", absolute seconds.
  {
    CloudBuilder cloud(20, false);
    cloud.NewPoint();
    cloud.Put(12, 1700000000.125);
    const PointCloud2Decoder decoder(With({{"timestamp", 12, kFloat64, 1}}), 20, false);
    const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 1, 1, 20, stamp);
    EXPECT_EQ(out.time_convention, PointTimeConvention::kAbsoluteSeconds);
    EXPECT_DOUBLE_EQ(out.scan.points[0].time_s, 1700000000.125);
  }
  // No time field: every point at the stamp, times left to the plugin.
  {
    CloudBuilder cloud(12, false);
    cloud.NewPoint();
    const PointCloud2Decoder decoder(kXyz, 12, false);
    const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 1, 1, 12, stamp);
    EXPECT_EQ(out.time_convention, PointTimeConvention::kNone);
    EXPECT_FALSE(out.scan.has_point_time);
    EXPECT_DOUBLE_EQ(out.scan.start_time_s, stamp);
    EXPECT_DOUBLE_EQ(out.scan.end_time_s, stamp);
  }
}

TEST(PointCloud2DecoderTest, BigEndianCloudsAndNonFinitePoints) {
  CloudBuilder cloud(16, true);
  cloud.NewPoint();
  cloud.Put(0, 1.5f);
  cloud.Put(4, 2.5f);
  cloud.Put(8, -3.5f);
  cloud.Put(12, 0.01f);
  cloud.NewPoint();  // an organised cloud's empty return
  cloud.Put(0, std::numeric_limits<float>::quiet_NaN());
  const PointCloud2Decoder decoder(With({{"time", 12, kFloat32, 1}}), 16, true);
  const CloudDecoding out = decoder.Decode(cloud.data().data(), cloud.data().size(), 1, 2, 16, 5.0);
  ASSERT_EQ(out.scan.points.size(), 1u);
  EXPECT_EQ(out.dropped, 1u);
  EXPECT_EQ(out.scan.points[0].position_m, Eigen::Vector3d(1.5, 2.5, -3.5));
  EXPECT_DOUBLE_EQ(out.scan.points[0].time_s, 5.0 + static_cast<double>(0.01f));
}

TEST(PointCloud2DecoderTest, MalformedLayoutsAreErrors) {
  // No z.
  EXPECT_THROW(PointCloud2Decoder({{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}}, 8, false), InputError);
  // A field past the end of the point.
  EXPECT_THROW(PointCloud2Decoder(With({{"intensity", 12, kFloat32, 1}}), 14, false), InputError);
  // Unknown datatype.
  EXPECT_THROW(PointCloud2Decoder(With({{"ring", 12, 9, 1}}), 16, false), InputError);
  // Data shorter than width x height points.
  const PointCloud2Decoder decoder(kXyz, 12, false);
  const std::vector<std::uint8_t> bytes(20, 0);
  EXPECT_THROW(decoder.Decode(bytes.data(), bytes.size(), 2, 1, 24, 0.0), InputError);
}

}  // namespace
}  // namespace unimap::io
