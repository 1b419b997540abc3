#include "io/DatasetReader.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "DatasetTestData.hpp"
#include "io/DatasetWriter.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ScratchFolder;

// These tests are about the format (a bit-exact round trip of any double,
// extremes included): the plausibility limits are tested in DatasetLimits_test.
const DatasetLimits kFormatOnly = DatasetLimits::Unlimited();
using test::ValueSource;

DatasetMetadata Meta() {
  DatasetMetadata m;
  m.source = "unimap simulate";
  m.payload = "rotating_2d";
  m.seed = 42;
  m.imu_rate_hz = 200.0;
  m.payload_parameters.Set("motor.rate_hz", 0.5);
  m.payload_parameters.Set("motor.axis", std::vector<double>{0.0, 0.0, 1.0});
  m.payload_parameters.Set("n", std::int64_t{40});
  m.payload_parameters.Set("name", std::string("hokuyo"));
  m.payload_parameters.Set("reverse", true);
  return m;
}

// Everything one dataset holds, in stream order.
struct Contents {
  std::vector<ImuSample> imu;
  std::vector<EncoderSample> encoder;
  std::vector<OdometrySample> odometry;
  std::vector<ScanRecord> scans;
  std::vector<StampedPose> truth;
};

Contents RandomContents(std::uint32_t seed) {
  ValueSource v(seed);
  Contents c;
  double t = 1.7e9;  // Unix-epoch-like times: the fractional digits must survive
  for (int i = 0; i < 300; ++i) {
    t += i % 7 == 0 ? 0.0 : v.Uniform(0.0, 0.01);  // some equal times
    c.imu.push_back(test::RandomImu(v, t));
    if (i % 3 == 0) c.encoder.push_back({t, v.Any()});
    if (i % 5 == 0) c.odometry.push_back({t, test::RandomPose(v)});
    if (i % 11 == 0) c.truth.push_back({t, test::RandomPose(v)});
    if (i % 10 == 0) {
      const int size = i % 20 == 0 ? v.Int(0, 50) : v.Int(0, 30);
      if (i % 20 == 0) {
        c.scans.emplace_back(test::RandomLine(v, t - 0.001, size));
      } else {
        c.scans.emplace_back(test::RandomRaw(v, t - 0.1, size));
      }
    }
  }
  c.scans.emplace_back(LineScan{});  // no beams, time 0: must come first to keep order
  std::rotate(c.scans.rbegin(), c.scans.rbegin() + 1, c.scans.rend());
  return c;
}

void Write(const std::filesystem::path& folder, const Contents& c) {
  DatasetWriter writer(folder, Meta());
  for (const auto& s : c.imu) writer.WriteImu(s);
  for (const auto& s : c.encoder) writer.WriteEncoder(s);
  for (const auto& s : c.odometry) writer.WriteOdometry(s);
  for (const auto& s : c.scans) writer.WriteScan(s);
  for (const auto& s : c.truth) writer.WriteGroundTruth(s);
  writer.Finish();
}

// The InputError message `read` throws.
template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

void ReadAll(const std::filesystem::path& folder) {
  DatasetReader reader(folder, kFormatOnly);
  while (reader.NextEvent()) {
  }
}

TEST(DatasetReader, AllStreamsRoundTripBitExactly) {
  ScratchFolder folder;
  const Contents written = RandomContents(1);
  Write(folder.path(), written);
  DatasetReader reader(folder.path(), kFormatOnly);
  EXPECT_EQ(reader.metadata().payload_parameters, Meta().payload_parameters);
  EXPECT_EQ(reader.metadata().seed, 42u);
  EXPECT_TRUE(reader.has_groundtruth());
  for (const auto& s : written.imu) test::ExpectSameImu(s, *reader.NextImu());
  EXPECT_FALSE(reader.NextImu());
  for (const auto& s : written.encoder) {
    const auto e = reader.NextEncoder();
    EXPECT_TRUE(test::SameBits(s.time_s, e->time_s));
    EXPECT_TRUE(test::SameBits(s.angle_rad, e->angle_rad));
  }
  EXPECT_FALSE(reader.NextEncoder());
  for (const auto& s : written.odometry) {
    const auto o = reader.NextOdometry();
    test::ExpectSamePose(s.time_s, s.T_odom_body, o->time_s, o->T_odom_body);
  }
  EXPECT_FALSE(reader.NextOdometry());
  for (const auto& s : written.scans) test::ExpectSameScan(s, *reader.NextScan());
  EXPECT_FALSE(reader.NextScan());
  for (const auto& s : written.truth) {
    const auto g = reader.NextGroundTruth();
    test::ExpectSamePose(s.time_s, s.T_map_body, g->time_s, g->T_map_body);
  }
  EXPECT_FALSE(reader.NextGroundTruth());
}

TEST(DatasetReader, NextEventMergesStreamsByTimeWithTiesInStreamOrder) {
  ScratchFolder folder;
  const Contents c = RandomContents(2);
  Write(folder.path(), c);
  // Expected order: by time, ties IMU < encoder < odometry < scan, file order within a stream.
  std::vector<std::tuple<double, int, std::size_t>> expected;
  for (std::size_t i = 0; i < c.imu.size(); ++i) expected.emplace_back(c.imu[i].time_s, 0, i);
  for (std::size_t i = 0; i < c.encoder.size(); ++i) {
    expected.emplace_back(c.encoder[i].time_s, 1, i);
  }
  for (std::size_t i = 0; i < c.odometry.size(); ++i) {
    expected.emplace_back(c.odometry[i].time_s, 2, i);
  }
  for (std::size_t i = 0; i < c.scans.size(); ++i) {
    expected.emplace_back(ScanEndTime(c.scans[i]), 3, i);
  }
  std::sort(expected.begin(), expected.end());
  DatasetReader reader(folder.path(), kFormatOnly);
  for (const auto& [time_s, stream, index] : expected) {
    const auto event = reader.NextEvent();
    ASSERT_TRUE(event.has_value());
    ASSERT_EQ(static_cast<int>(event->index()), stream) << "at t = " << time_s;
    if (stream == 0) {
      test::ExpectSameImu(c.imu[index], std::get<ImuSample>(*event));
    } else if (stream == 1) {
      EXPECT_EQ(std::get<EncoderSample>(*event).angle_rad, c.encoder[index].angle_rad);
    } else if (stream == 2) {
      EXPECT_EQ(std::get<OdometrySample>(*event).time_s, c.odometry[index].time_s);
    } else {
      test::ExpectSameScan(c.scans[index], std::get<ScanRecord>(*event));
    }
  }
  EXPECT_FALSE(reader.NextEvent());
}

TEST(DatasetReader, PerStreamCallsAfterNextEventReturnTheHeldItemFirst) {
  ScratchFolder folder;
  DatasetWriter writer(folder.path(), Meta());
  writer.WriteImu(ImuSample{1.0, {}, {}});
  writer.WriteEncoder({2.0, 0.5});
  writer.WriteEncoder({3.0, 0.6});
  writer.Finish();
  DatasetReader reader(folder.path(), kFormatOnly);
  ASSERT_TRUE(std::holds_alternative<ImuSample>(*reader.NextEvent()));  // encoder 2.0 now held
  EXPECT_EQ(reader.NextEncoder()->time_s, 2.0);
  EXPECT_EQ(reader.NextEncoder()->time_s, 3.0);
  EXPECT_FALSE(reader.NextEncoder());
}

TEST(DatasetReader, MalformedImuLineNamesFileAndLine) {
  ScratchFolder folder;
  Write(folder.path(), RandomContents(3));
  std::string text = test::ReadText(folder / "imu.csv");
  std::size_t pos = 0;
  for (int i = 0; i < 3; ++i) pos = text.find('\n', pos) + 1;  // start of line 4
  text.insert(text.find(' ', pos) + 1, "x");
  test::WriteText(folder / "imu.csv", text);
  const std::string error = ErrorOf([&] { ReadAll(folder.path()); });
  EXPECT_NE(error.find("imu.csv:4: field 2"), std::string::npos) << error;

  test::WriteText(folder / "imu.csv", "# header\n1 2 3 4 5 6 7\n\n2 2 3 4 5 6\n");
  EXPECT_NE(ErrorOf([&] { ReadAll(folder.path()); }).find("imu.csv:4: expected 7 numbers, found 6"), std::string::npos);
  test::WriteText(folder / "imu.csv", "2 0 0 0 0 0 0\n1 0 0 0 0 0 0\n");
  EXPECT_NE(ErrorOf([&] { ReadAll(folder.path()); }).find("imu.csv:2: time goes backwards"), std::string::npos);
  test::WriteText(folder / "imu.csv", "nan 0 0 0 0 0 0\n");
  EXPECT_NE(ErrorOf([&] { ReadAll(folder.path()); }).find("imu.csv:1: time nan is not finite"), std::string::npos);
}

TEST(DatasetReader, NonUnitQuaternionNamesFileAndLine) {
  ScratchFolder folder;
  Write(folder.path(), RandomContents(4));
  test::WriteText(folder / "odometry.csv", "# t x y z qx qy qz qw\n0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 2\n");
  const std::string error = ErrorOf([&] {
    DatasetReader reader(folder.path(), kFormatOnly);
    while (reader.NextOdometry()) {
    }
  });
  EXPECT_NE(error.find("odometry.csv:3: quaternion"), std::string::npos) << error;
}

TEST(DatasetReader, MissingOrIncompleteDatasetsGiveClearErrors) {
  ScratchFolder folder;
  EXPECT_NE(ErrorOf([&] { DatasetReader reader(folder / "nowhere", kFormatOnly); }).find("no such dataset"),
            std::string::npos);
  test::WriteText(folder / "imu.csv", "0 0 0 0 0 0 0\n");
  test::WriteText(folder / "metadata.yaml.partial", "format_version: 1\npayload: x\n");
  EXPECT_NE(ErrorOf([&] { DatasetReader reader(folder.path(), kFormatOnly); }).find("no metadata.yaml"),
            std::string::npos);
  test::WriteText(folder / "metadata.yaml", "format_version: 2\npayload: x\n");
  EXPECT_THROW(DatasetReader reader(folder.path(), kFormatOnly), ConfigError);
}

TEST(DatasetReader, PartialFilesAreIgnored) {
  ScratchFolder folder;
  DatasetWriter writer(folder.path(), Meta());
  writer.WriteImu(ImuSample{1.0, {}, {}});
  writer.Finish();
  test::WriteText(folder / "encoder.csv.partial", "0 0\n");
  DatasetReader reader(folder.path(), kFormatOnly);
  EXPECT_FALSE(reader.NextEncoder());
  EXPECT_TRUE(std::holds_alternative<ImuSample>(*reader.NextEvent()));
  EXPECT_FALSE(reader.NextEvent());
}

// 1,000 scans of 256 points (~10 MB): read back in order, and the reader is
// shown to stream: the file's tail is cut after the first scan was read and
// everything before the cut still comes back (nothing was loaded up front).
TEST(DatasetReader, StreamsALargeScanFile) {
  ScratchFolder folder;
  constexpr int kScans = 1000;
  {
    ValueSource v(5);
    DatasetWriter writer(folder.path(), Meta());
    for (int i = 0; i < kScans; ++i) writer.WriteScan(test::RandomRaw(v, 0.1 * i, 256));
    writer.Finish();
  }
  const auto file = folder / "scans.bin";
  const std::uintmax_t size = std::filesystem::file_size(file);
  ASSERT_EQ(size, 12u + kScans * (5u + 21u + 256u * 38u));
  ValueSource v(5);  // regenerates the same scans
  DatasetReader reader(folder.path(), kFormatOnly);
  test::ExpectSameScan(test::RandomRaw(v, 0.0, 256), *reader.NextScan());
  std::filesystem::resize_file(file, size - 100);  // cuts into the last record
  for (int i = 1; i < kScans - 1; ++i) {
    const auto scan = reader.NextEvent();
    ASSERT_TRUE(scan.has_value());
    test::ExpectSameScan(test::RandomRaw(v, 0.1 * i, 256), std::get<ScanRecord>(*scan));
    if (::testing::Test::HasFailure()) return;
  }
  const std::string error = ErrorOf([&] { reader.NextScan(); });
  EXPECT_NE(error.find("scans.bin: record 1000"), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
}

}  // namespace
}  // namespace unimap::io
