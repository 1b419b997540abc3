#include "io/CarmenReader.hpp"

#include <bzlib.h>
#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::WriteText;

namespace fs = std::filesystem;

fs::path Radish(const char* name) { return fs::path(UNIMAP_SHARED_DATA_DIR) / "radish" / name; }

#define SKIP_IF_MISSING(path) \
  if (!fs::exists(path)) GTEST_SKIP() << "real data absent: " << (path) << " (../shared/data not present)"

// bzip2-compresses `text` into `file` with libbz2.
void WriteBzip2(const fs::path& file, const std::string& text) {
  std::string out(text.size() + text.size() / 100 + 600, '\0');
  auto size = static_cast<unsigned int>(out.size());
  std::string in = text;
  ASSERT_EQ(BZ2_bzBuffToBuffCompress(out.data(), &size, in.data(), static_cast<unsigned int>(in.size()), 9, 0, 0),
            BZ_OK);
  out.resize(size);
  WriteText(file, out);
}

// Counts of one log, read to the end.
struct LogCounts {
  std::size_t scans = 0, odometry = 0;
  std::size_t beams_min = SIZE_MAX, beams_max = 0;
  double angle_min = 0.0, angle_increment = 0.0, range_max = 0.0;
};

LogCounts ReadAll(CarmenReader* reader) {
  LogCounts counts;
  while (auto message = reader->Next()) {
    if (const auto* laser = std::get_if<CarmenLaser>(&*message)) {
      ++counts.scans;
      counts.beams_min = std::min(counts.beams_min, laser->scan.ranges_m.size());
      counts.beams_max = std::max(counts.beams_max, laser->scan.ranges_m.size());
      counts.angle_min = laser->scan.angle_min_rad;
      counts.angle_increment = laser->scan.angle_increment_rad;
      counts.range_max = laser->scan.range_max_m;
    } else {
      ++counts.odometry;
    }
  }
  return counts;
}

constexpr double kPi = 3.14159265358979323846;

// ---- The real logs: counts from the data set's own README (and the files).

TEST(CarmenReaderTest, IntelLogHas13631ScansOf180BeamsAnd26915Odom) {
  const fs::path log = Radish("intel.clf.bz2");
  SKIP_IF_MISSING(log);
  CarmenReader reader(log);
  const LogCounts counts = ReadAll(&reader);
  EXPECT_EQ(counts.scans, 13631u);
  EXPECT_EQ(counts.beams_min, 180u);
  EXPECT_EQ(counts.beams_max, 180u);
  EXPECT_EQ(counts.odometry, 26915u);
  // 180 beams over 180 deg: 1 deg apart from -90 deg.
  EXPECT_DOUBLE_EQ(counts.angle_min, -kPi / 2);
  EXPECT_DOUBLE_EQ(counts.angle_increment, kPi / 180);
  EXPECT_DOUBLE_EQ(counts.range_max, 80.0);
  EXPECT_EQ(reader.stats().other_messages.at("PARAM"), 2u);
  EXPECT_TRUE(reader.stats().skipped.empty());
  EXPECT_FALSE(reader.stats().truncated_input);
}

TEST(CarmenReaderTest, Fr079LogHas4934ScansOf360BeamsAnd8951Odom) {
  const fs::path log = Radish("fr079.clf.bz2");
  SKIP_IF_MISSING(log);
  CarmenReader reader(log);
  const LogCounts counts = ReadAll(&reader);
  EXPECT_EQ(counts.scans, 4934u);
  // The file's FLASER lines all hold 360 ranges (as the README says): 0.5 deg from -90 deg.
  EXPECT_EQ(counts.beams_min, 360u);
  EXPECT_EQ(counts.beams_max, 360u);
  EXPECT_DOUBLE_EQ(counts.angle_increment, kPi / 360);
  EXPECT_EQ(counts.odometry, 8951u);
  EXPECT_EQ(reader.stats().other_messages.at("PARAM"), 187u);
}

TEST(CarmenReaderTest, MitCsailLogHas1988ScansOf361BeamsAndNoOdom) {
  const fs::path log = Radish("mit-csail.clf.bz2");
  SKIP_IF_MISSING(log);
  EXPECT_FALSE(CarmenReader::HasOdometryLines(log));
  CarmenReader reader(log);
  const LogCounts counts = ReadAll(&reader);
  EXPECT_EQ(counts.scans, 1988u);
  EXPECT_EQ(counts.beams_min, 361u);
  EXPECT_EQ(counts.beams_max, 361u);
  EXPECT_EQ(counts.odometry, 0u);
  // 361 beams include both ends: -90 .. +90 deg in 0.5 deg steps.
  EXPECT_DOUBLE_EQ(counts.angle_min + 360 * counts.angle_increment, kPi / 2);
}

// ---- Fixtures.

const char* const kFixture =
    "# CARMEN Logfile\n"
    "PARAM robot_front_laser_max 80.99 1.0 host 1.0\n"
    "FLASER 4 1.5 2.0 81.91 3.25 1.0 2.0 0.5 1.1 2.1 0.6 100.25 host 0.25\n"
    "ODOM 1.0 2.0 1.5707963267948966 0.3 0.1 0.0 100.30 host 0.30\n"
    "\n"
    "RLASER 1 1.0 0 0 0 0 0 0 100.35 host 0.35\n"
    "ODOM 1.1 2.1 0.0 0.3 0.1 0.0 100.40 host 0.40\n";

TEST(CarmenReaderTest, ParsesFlaserAndOdomFieldsExactly) {
  test::ScratchFolder dir;
  WriteText(dir.path() / "a.clf", kFixture);
  CarmenReader reader(dir.path() / "a.clf");
  auto first = reader.Next();
  ASSERT_TRUE(first.has_value());
  const auto& laser = std::get<CarmenLaser>(*first);
  EXPECT_EQ(laser.line, 3);
  EXPECT_EQ(laser.scan.ranges_m, (std::vector<float>{1.5f, 2.0f, 81.91f, 3.25f}));
  EXPECT_DOUBLE_EQ(laser.scan.start_time_s, 100.25);  // ipc timestamp
  EXPECT_DOUBLE_EQ(laser.scan.angle_min_rad, -kPi / 2);
  EXPECT_DOUBLE_EQ(laser.scan.angle_increment_rad, kPi / 4);  // 4 beams over 180 deg
  EXPECT_DOUBLE_EQ(laser.scan.time_increment_s, 0.0);
  EXPECT_EQ(laser.pose_xytheta, Eigen::Vector3d(1.0, 2.0, 0.5));
  EXPECT_DOUBLE_EQ(laser.odometry.time_s, 100.25);
  EXPECT_TRUE(laser.odometry.T_odom_body.translation().isApprox(Eigen::Vector3d(1.1, 2.1, 0.0)));
  EXPECT_NEAR(Eigen::AngleAxisd(laser.odometry.T_odom_body.linear()).angle(), 0.6, 1e-12);

  auto second = reader.Next();
  ASSERT_TRUE(second.has_value());
  const auto& odom = std::get<CarmenOdometry>(*second);
  EXPECT_EQ(odom.line, 4);
  EXPECT_DOUBLE_EQ(odom.odometry.time_s, 100.30);
  EXPECT_DOUBLE_EQ(odom.tv_m_s, 0.3);
  EXPECT_DOUBLE_EQ(odom.rv_rad_s, 0.1);
  // theta = pi/2: the body x axis points along odom +y.
  EXPECT_TRUE(
      (odom.odometry.T_odom_body.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));

  ASSERT_TRUE(reader.Next().has_value());
  EXPECT_FALSE(reader.Next().has_value());
  const CarmenReaderStats& stats = reader.stats();
  EXPECT_EQ(stats.laser_scans, 1u);
  EXPECT_EQ(stats.odometry, 2u);
  EXPECT_EQ(stats.comments, 2u);  // the '#' line and the blank line
  EXPECT_EQ(stats.other_messages.at("PARAM"), 1u);
  EXPECT_EQ(stats.other_messages.at("RLASER"), 1u);
}

TEST(CarmenReaderTest, MalformedLineInsideTheLogIsAnErrorNamingFileAndLine) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "bad.clf";
  WriteText(file,
            "# log\n"
            "ODOM 1 2 3 0 0 0 10.0 host 10.0\n"
            "FLASER 3 1.0 2.0 0.0 0.0 0.0 0.0 0.0 0.0 10.1 host 10.1\n"  // 3 beams announced, 2 given
            "ODOM 1 2 3 0 0 0 10.2 host 10.2\n");
  CarmenReader reader(file);
  ASSERT_TRUE(reader.Next().has_value());
  try {
    reader.Next();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string() + ":3:"), std::string::npos) << what;
    EXPECT_NE(what.find("FLASER with 3 beams"), std::string::npos) << what;
  }
}

TEST(CarmenReaderTest, NonNumericFieldIsAnErrorNamingTheLine) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "bad.clf";
  WriteText(file, "ODOM 1 2 x 0 0 0 10.0 host 10.0\nODOM 1 2 3 0 0 0 10.2 host 10.2\n");
  CarmenReader reader(file);
  EXPECT_THROW(
      {
        try {
          reader.Next();
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find(":1: ODOM field 'x'"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}

// The InputError message of reading the whole log (a failure if none).
std::string ReadAllError(const fs::path& file) {
  try {
    CarmenReader reader(file);
    ReadAll(&reader);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << file;
  return {};
}

TEST(CarmenReaderTest, HugeOrJumpingTimestampIsAnErrorNamingTheLine) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "clock.clf";
  // Before, a 1e300 stamp made the dataset last 1e300 s and the later scans were dropped unnamed.
  WriteText(file,
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\n"
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1e300 host 10.2\n"
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.3 host 10.3\n");
  EXPECT_NE(ReadAllError(file).find("clock.clf:2: ipc timestamp 1e+300 s is beyond +-1e+10 s"), std::string::npos)
      << ReadAllError(file);
  WriteText(file,
            "ODOM 1 2 3 0 0 0 10.0 host 10.0\n"
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\n"
            "ODOM 1 2 3 0 0 0 1000010.2 host 10.2\n");
  EXPECT_NE(ReadAllError(file).find("clock.clf:3: ipc timestamp 1000010.2 s jumps "), std::string::npos)
      << ReadAllError(file);
  // The Intel log's real 3.5 s pause is well within the 60 s limit.
  WriteText(file,
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\n"
            "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 13.6 host 13.6\n");
  CarmenReader reader(file);
  EXPECT_EQ(ReadAll(&reader).scans, 2u);
}

TEST(CarmenReaderTest, TruncatedLastLineIsACountedSkip) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "cut.clf";
  // The logger died mid-line: no newline, fields missing.
  WriteText(file, "ODOM 1 2 3 0 0 0 10.0 host 10.0\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\nFLASER 3 1.0 2.");
  CarmenReader reader(file);
  const LogCounts counts = ReadAll(&reader);
  EXPECT_EQ(counts.odometry, 1u);
  EXPECT_EQ(counts.scans, 1u);
  ASSERT_EQ(reader.stats().skipped.size(), 1u);
  EXPECT_EQ(reader.stats().skipped.at("truncated last line (FLASER)"), 1u);
  ASSERT_EQ(reader.stats().skipped_lines.size(), 1u);
  EXPECT_EQ(reader.stats().skipped_lines[0].line, 3);
}

TEST(CarmenReaderTest, Bzip2LogReadsLikeThePlainOneAndTruncationIsReported) {
  test::ScratchFolder dir;
  WriteBzip2(dir.path() / "a.clf.bz2", kFixture);
  CarmenReader reader(dir.path() / "a.clf.bz2");
  const LogCounts counts = ReadAll(&reader);
  EXPECT_EQ(counts.scans, 1u);
  EXPECT_EQ(counts.odometry, 2u);
  EXPECT_FALSE(reader.stats().truncated_input);

  // Cut the compressed file: the block cannot be decoded, nothing is
  // delivered, and the reader says the data ended early (no crash, no throw).
  const std::string whole = [&] {
    std::ifstream in(dir.path() / "a.clf.bz2", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  WriteText(dir.path() / "cut.clf.bz2", whole.substr(0, whole.size() / 2));
  CarmenReader cut(dir.path() / "cut.clf.bz2");
  ReadAll(&cut);
  EXPECT_TRUE(cut.stats().truncated_input);
}

TEST(CarmenReaderTest, CorruptBzip2DataIsAnError) {
  test::ScratchFolder dir;
  std::string bytes = "BZh91AY&SY";
  bytes += std::string(200, '\x5a');
  WriteText(dir.path() / "x.clf.bz2", bytes);
  CarmenReader reader(dir.path() / "x.clf.bz2");
  EXPECT_THROW(ReadAll(&reader), InputError);
}

TEST(CarmenReaderTest, MissingFileIsAnError) {
  EXPECT_THROW(CarmenReader(fs::path("/nonexistent/unimap/log.clf")), InputError);
}

// ---- Conversion round trips.

// Counts what a dataset folder holds.
LogCounts ReadDataset(const fs::path& folder) {
  DatasetReader reader(folder);
  LogCounts counts;
  while (auto scan = reader.NextScan()) {
    ++counts.scans;
    const auto& line = std::get<LineScan>(*scan);
    counts.beams_min = std::min(counts.beams_min, line.ranges_m.size());
    counts.beams_max = std::max(counts.beams_max, line.ranges_m.size());
  }
  while (reader.NextOdometry()) ++counts.odometry;
  return counts;
}

TEST(CarmenReaderTest, OutOfOrderFixtureConvertsInTimeOrder) {
  test::ScratchFolder dir;
  WriteText(dir.path() / "a.clf",
            "FLASER 2 1 1 0 0 0 0 0 0 10.0 h 1\n"
            "FLASER 2 1 1 0 0 0 0 0 0 10.5 h 1\n"
            "FLASER 2 1 1 0 0 0 0 0 0 10.2 h 1\n"  // delivered late, as in intel.clf
            "FLASER 2 1 1 0 0 0 0 0 0 10.7 h 1\n");
  ConversionOptions options;
  options.input = dir.path() / "a.clf";
  options.output = dir.path() / "out";
  const ConversionReport report = ConvertCarmen(options);
  EXPECT_EQ(report.scans, 4u);
  EXPECT_EQ(report.odometry, 4u);  // no ODOM lines: from the FLASER fields
  EXPECT_TRUE(report.skipped.empty());
  DatasetReader reader(options.output);
  std::vector<double> times;
  while (auto scan = reader.NextScan()) times.push_back(std::get<LineScan>(*scan).start_time_s);
  EXPECT_EQ(times, (std::vector<double>{10.0, 10.2, 10.5, 10.7}));
}

TEST(CarmenReaderTest, IntelRoundTripKeepsEveryScanAndOdometryLine) {
  const fs::path log = Radish("intel.clf.bz2");
  SKIP_IF_MISSING(log);
  test::ScratchFolder dir;
  ConversionOptions options;
  options.input = log;
  options.output = dir.path() / "intel";
  const ConversionReport report = ConvertCarmen(options);
  // 631 scans arrive up to 0.9 s late; the 2 s reorder window places them all.
  EXPECT_EQ(report.scans, 13631u);
  EXPECT_EQ(report.odometry, 26915u);
  EXPECT_EQ(report.skipped.at("PARAM lines (not converted)"), 2u);
  EXPECT_EQ(report.skipped.size(), 1u);
  const LogCounts counts = ReadDataset(options.output);
  EXPECT_EQ(counts.scans, 13631u);
  EXPECT_EQ(counts.beams_min, 180u);
  EXPECT_EQ(counts.beams_max, 180u);
  EXPECT_EQ(counts.odometry, 26915u);
}

TEST(CarmenReaderTest, MitCsailRoundTripTakesOdometryFromFlaserFields) {
  const fs::path log = Radish("mit-csail.clf.bz2");
  SKIP_IF_MISSING(log);
  test::ScratchFolder dir;
  ConversionOptions options;
  options.input = log;
  options.output = dir.path() / "mit";
  const ConversionReport report = ConvertCarmen(options);
  EXPECT_EQ(report.scans, 1988u);
  EXPECT_EQ(report.odometry, 1988u);
  const LogCounts counts = ReadDataset(options.output);
  EXPECT_EQ(counts.scans, 1988u);
  EXPECT_EQ(counts.beams_min, 361u);
  EXPECT_EQ(counts.odometry, 1988u);
}

}  // namespace
}  // namespace unimap::io
