#include "io/DatasetLimits.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/DatasetReader.hpp"
#include "io/DatasetWriter.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ScratchFolder;

// A dataset folder with metadata.yaml and the given text streams.
void WriteDataset(const ScratchFolder& folder, const std::string& imu, const std::string& encoder = "",
                  const std::string& odometry = "") {
  for (const char* name : {"imu.csv", "encoder.csv", "odometry.csv"}) std::filesystem::remove(folder / name);
  test::WriteText(folder / "metadata.yaml", "format_version: 1\npayload: rotating_2d\n");
  if (!imu.empty()) test::WriteText(folder / "imu.csv", imu);
  if (!encoder.empty()) test::WriteText(folder / "encoder.csv", encoder);
  if (!odometry.empty()) test::WriteText(folder / "odometry.csv", odometry);
}

// The InputError message of reading every event of the folder ("" if none).
std::string ReadError(const ScratchFolder& folder) {
  try {
    DatasetReader reader(folder.path());
    while (reader.NextEvent()) {
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

// n IMU rows at rest, 0.005 s apart from t0, then `last`.
std::string ImuRows(int n, double t0, const std::string& last) {
  std::string text = "# time_s ax ay az gx gy gz\n";
  for (int i = 0; i < n; ++i) text += std::to_string(t0 + 0.005 * i) + " 0 0 9.81 0 0 0\n";
  return text + last;
}

::testing::AssertionResult Has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" lacks \"" << part << "\"";
}

TEST(DatasetLimits, DefaultsComeFromDatasheetsAndAreValid) {
  const DatasetLimits limits;
  EXPECT_NEAR(limits.max_accel_m_s2, 392.27, 0.01);   // 40 g
  EXPECT_NEAR(limits.max_gyro_rad_s, 69.813, 0.001);  // 4000 deg/s
  std::string why;
  EXPECT_TRUE(limits.IsValid(&why)) << why;
  EXPECT_TRUE(DatasetLimits::Unlimited().IsValid(&why)) << why;
  DatasetLimits bad;
  bad.max_imu_step_s = std::nan("");
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_THROW(DatasetReader(std::filesystem::path("/nonexistent"), bad), ConfigError);
}

TEST(DatasetLimits, ImplausibleImuValueNamesFileLineAndLimit) {
  ScratchFolder folder;
  // Line 301: the header, then 299 good rows, then 1e300 on the accelerometer's x.
  WriteDataset(folder, ImuRows(299, 0.0, "1.495 1e300 0 9.81 0 0 0\n"));
  EXPECT_TRUE(Has(ReadError(folder), "imu.csv:301: accelerometer x 1e+300 m/s^2 is beyond +-392.3 m/s^2"));
  WriteDataset(folder, ImuRows(3, 0.0, "0.015 0 0 9.81 0 0 -80\n"));
  EXPECT_TRUE(Has(ReadError(folder), "imu.csv:5: gyroscope z -80 rad/s is beyond +-69.81 rad/s"));
  WriteDataset(folder, ImuRows(3, 0.0, "0.015 0 nan 9.81 0 0 0\n"));
  EXPECT_TRUE(Has(ReadError(folder), "imu.csv:5: accelerometer y nan m/s^2 is not a number"));
  // At the limit is a reading (a saturated one).
  WriteDataset(folder, ImuRows(3, 0.0, "0.015 392 -392 9.81 69.8 0 -69.8\n"));
  EXPECT_EQ(ReadError(folder), "");
}

TEST(DatasetLimits, ImuClockJumpIsAnErrorNotAGapToIntegrate) {
  ScratchFolder folder;
  WriteDataset(folder, ImuRows(10, 0.0, "1000000.05 0 0 9.81 0 0 0\n"));
  const std::string jump = ReadError(folder);
  EXPECT_TRUE(Has(jump, "imu.csv:12: time jumps 1000000.00"));
  EXPECT_TRUE(Has(jump,
                  "s ahead (1000000.05 s after 0.045 s), more than the 1 s a sample may follow the previous one: "
                  "a clock jump or lost data"));
  // A 0.5 s gap is lost data the filter bridges (counted there), not a reader error.
  WriteDataset(folder, ImuRows(10, 0.0, "0.545 0 0 9.81 0 0 0\n"));
  EXPECT_EQ(ReadError(folder), "");
  WriteDataset(folder, ImuRows(0, 0.0, "1e300 0 0 9.81 0 0 0\n"));
  EXPECT_TRUE(Has(ReadError(folder), "imu.csv:2: time 1e+300 s is beyond +-1e+10 s (not a plausible clock)"));
}

TEST(DatasetLimits, EncoderAndOdometryValuesAndSteps) {
  ScratchFolder folder;
  WriteDataset(folder, "", "0 0.1\n0.01 1e300\n");
  EXPECT_TRUE(Has(ReadError(folder), "encoder.csv:2: encoder angle 1e+300 rad is beyond +-1e+09 rad"));
  WriteDataset(folder, "", "0 0.1\n20 0.2\n");
  EXPECT_TRUE(Has(ReadError(folder), "encoder.csv:2: time jumps 20 s ahead"));
  WriteDataset(folder, "", "0 0.1\n5 0.2\n");  // lost data: the scans in the gap are skipped downstream
  EXPECT_EQ(ReadError(folder), "");
  WriteDataset(folder, "", "", "0 0 0 0 0 0 0 1\n0.1 3e8 0 0 0 0 0 1\n");
  EXPECT_TRUE(Has(ReadError(folder), "odometry.csv:2: position x 3e+08 m is beyond +-1e+08 m"));
  WriteDataset(folder, "", "", "0 0 0 0 0 0 0 1\n61 1 0 0 0 0 0 1\n");
  EXPECT_TRUE(Has(ReadError(folder), "odometry.csv:2: time jumps 61 s ahead"));
}

TEST(DatasetLimits, ScanStepAndDurationNameTheRecord) {
  ScratchFolder folder;
  const auto raw = [](double start_s, double end_s) {
    RawScan scan;
    scan.start_time_s = start_s;
    scan.end_time_s = end_s;
    return ScanRecord(scan);
  };
  {
    DatasetWriter writer(folder.path(), DatasetMetadata{});
    writer.WriteScan(raw(0.0, 0.1));
    writer.WriteScan(raw(0.1, 0.2));
    writer.WriteScan(raw(1e6, 1e6 + 0.1));
    writer.Finish();
  }
  EXPECT_TRUE(Has(ReadError(folder), "scans.bin: record 3 (byte "));
  EXPECT_TRUE(Has(ReadError(folder),
                  "s ahead (the scan ends at 1000000.1 s, the previous one at 0.2 s), more than "
                  "the 60 s a scan may follow the previous one"));
  {
    DatasetWriter writer(folder.path(), DatasetMetadata{});
    writer.WriteScan(raw(0.0, 100.0));
    writer.Finish();
  }
  EXPECT_TRUE(Has(ReadError(folder), "scans.bin: record 1 (byte 12): scan lasts 100 s, longer than 10 s"));
  // The same files read without limits: the format alone accepts them.
  DatasetReader reader(folder.path(), DatasetLimits::Unlimited());
  EXPECT_TRUE(reader.NextScan().has_value());
}

TEST(DatasetLimits, LineScanGeometryMustBeFinite) {
  const DatasetLimits limits;
  LineScan line;
  line.ranges_m = {1.0f, 2.0f};
  line.time_increment_s = 0.001;
  line.angle_increment_rad = std::nan("");
  EXPECT_TRUE(Has(limits.ScanProblem(line), "angle_min_rad / angle_increment_rad are not finite"));
  line.angle_increment_rad = 0.01;
  line.range_min_m = 2.0;
  line.range_max_m = 1.0;
  EXPECT_TRUE(Has(limits.ScanProblem(line), "range limits [2, 1] m are not 0 <= range_min_m <= range_max_m"));
  line.range_max_m = 30.0;
  EXPECT_EQ(limits.ScanProblem(line), "");
}

}  // namespace
}  // namespace unimap::io
