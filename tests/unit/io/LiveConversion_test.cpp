#include "io/LiveConversion.hpp"

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;
using test::WriteText;

// A KITTI-layout sequence of `frames` .bin sweeps (frame k: k + 1 points),
// times k * 0.1 s (or `times`), identity poses.
void WriteSequence(const fs::path& root, int frames, const std::vector<double>& times = {}) {
  fs::create_directories(root / "velodyne");
  std::string times_text, poses_text;
  for (int k = 0; k < frames; ++k) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d.bin", k);
    std::vector<float> xyzi;
    for (int i = 0; i <= k; ++i) xyzi.insert(xyzi.end(), {1.0f + static_cast<float>(i), 2.0f, 3.0f, 0.5f});
    std::ofstream out(root / "velodyne" / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(xyzi.data()), static_cast<std::streamsize>(xyzi.size() * sizeof(float)));
    times_text += std::to_string(times.empty() ? 0.1 * k : times[static_cast<std::size_t>(k)]) + "\n";
    poses_text += "1 0 0 0 0 1 0 0 0 0 1 " + std::to_string(0.5 * k) + "\n";
  }
  WriteText(root / "times.txt", times_text);
  WriteText(root / "poses.txt", poses_text);
}

ConversionOptions Input(const fs::path& input) {
  ConversionOptions options;
  options.input = input;
  return options;
}

std::size_t Points(const ScanRecord& scan) { return std::get<RawScan>(scan).points.size(); }

TEST(LiveConversionTest, ASequenceReadDirectlyGivesTheEventsOfItsConvertedDataset) {
  test::ScratchFolder dir;
  WriteSequence(dir / "seq", 12);
  ConversionOptions convert = Input(dir / "seq");
  convert.output = dir / "data";
  ConvertKitti(convert);

  DatasetReader folder(dir / "data");
  DatasetReader live("kitti", Input(dir / "seq"));
  EXPECT_EQ(live.metadata().source, folder.metadata().source);
  EXPECT_EQ(live.metadata().payload, folder.metadata().payload);
  EXPECT_EQ(live.metadata().camera_from_lidar, folder.metadata().camera_from_lidar);
  EXPECT_FALSE(live.has_imu());
  std::size_t events = 0;
  while (const std::optional<DatasetEvent> expected = folder.NextEvent()) {
    const std::optional<DatasetEvent> got = live.NextEvent();
    ASSERT_TRUE(got.has_value()) << "event " << events;
    const auto& a = std::get<RawScan>(std::get<ScanRecord>(*expected));
    const auto& b = std::get<RawScan>(std::get<ScanRecord>(*got));
    EXPECT_EQ(a.start_time_s, b.start_time_s);
    EXPECT_EQ(a.end_time_s, b.end_time_s);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i].position_m, b.points[i].position_m);
    ++events;
  }
  EXPECT_EQ(events, 12u);
  EXPECT_FALSE(live.NextEvent().has_value());
  EXPECT_EQ(live.late_events(), 0u);
  // The ground truth, and the conversion's report once it has ended.
  ASSERT_TRUE(live.has_groundtruth());
  std::size_t poses = 0;
  while (const std::optional<StampedPose> pose = live.NextGroundTruth()) {
    EXPECT_NEAR(pose->T_map_body.translation().norm(), 0.5 * static_cast<double>(poses), 1e-9);
    ++poses;
  }
  EXPECT_EQ(poses, 12u);
  const std::optional<ConversionReport> report = live.conversion_report();
  ASSERT_TRUE(report.has_value());
  EXPECT_EQ(report->scans, 12u);
  EXPECT_EQ(report->groundtruth, 12u);
}

// Time of an event (scans by their end), and which stream it is from.
std::pair<double, std::size_t> TimeAndKind(const DatasetEvent& event) { return {EventTime(event), event.index()}; }

// The Intel Research Lab log: 631 laser lines arrive up to 0.9 s late and
// the odometry comes from ODOM lines, so the conversion reorders two
// streams; read directly, the merged events are those of its dataset.
TEST(LiveConversionTest, TheIntelLogReadDirectlyGivesTheEventsOfItsConvertedDataset) {
  const fs::path log = fs::path(UNIMAP_SHARED_DATA_DIR) / "radish" / "intel.clf.bz2";
  if (!fs::exists(log)) GTEST_SKIP() << "real data absent: " << log;
  test::ScratchFolder dir;
  ConversionOptions convert = Input(log);
  convert.output = dir / "data";
  ConvertCarmen(convert);
  DatasetReader folder(dir / "data");
  DatasetReader live("carmen", Input(log));
  std::size_t events = 0, scans = 0;
  while (const std::optional<DatasetEvent> expected = folder.NextEvent()) {
    const std::optional<DatasetEvent> got = live.NextEvent();
    ASSERT_TRUE(got.has_value()) << "event " << events;
    ASSERT_EQ(TimeAndKind(*expected), TimeAndKind(*got)) << "event " << events;
    if (const auto* line = std::get_if<ScanRecord>(&*got)) {
      ASSERT_EQ(std::get<LineScan>(*line).ranges_m, std::get<LineScan>(std::get<ScanRecord>(*expected)).ranges_m);
      ++scans;
    }
    ++events;
  }
  EXPECT_FALSE(live.NextEvent().has_value());
  EXPECT_EQ(scans, 13631u);
  EXPECT_EQ(events, 13631u + 26915u);
  EXPECT_EQ(live.late_events(), 0u);
}

TEST(LiveConversionTest, QueuesOfOneScanStillDeliverEveryScanInOrder) {
  test::ScratchFolder dir;
  WriteSequence(dir / "seq", 30);
  LiveConversion::QueueLimits limits;
  limits.max_items = 2;
  limits.max_scans = 1;
  LiveConversion live("kitti", Input(dir / "seq"), limits);
  for (std::size_t k = 0; k < 30; ++k) {
    // A stream the recording does not have answers at once when the queues are full.
    EXPECT_FALSE(live.NextImu().has_value());
    const std::optional<ScanRecord> scan = live.NextScan();
    ASSERT_TRUE(scan.has_value()) << "scan " << k;
    EXPECT_EQ(Points(*scan), k + 1);
  }
  EXPECT_FALSE(live.NextScan().has_value());
  EXPECT_TRUE(live.report().has_value());
}

TEST(LiveConversionTest, AReadErrorComesAfterTheScansBeforeItAndNamesTheFile) {
  test::ScratchFolder dir;
  WriteSequence(dir / "seq", 6);
  WriteText(dir / "seq" / "velodyne" / "000004.bin", "0123456789");  // 10 bytes: not whole points
  DatasetReader live("kitti", Input(dir / "seq"));
  std::size_t scans = 0;
  try {
    while (live.NextEvent()) ++scans;
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("000004.bin"), std::string::npos) << e.what();
  }
  EXPECT_EQ(scans, 4u);
  EXPECT_FALSE(live.conversion_report().has_value());
}

TEST(LiveConversionTest, AClockJumpIsAnErrorNamingTheInputStreamAndItem) {
  test::ScratchFolder dir;
  WriteSequence(dir / "seq", 4, {0.0, 0.1, 500.0, 500.1});
  DatasetReader live("kitti", Input(dir / "seq"));
  ASSERT_TRUE(live.NextEvent().has_value());
  ASSERT_TRUE(live.NextEvent().has_value());
  try {
    live.NextEvent();
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((dir / "seq").string() + ": scans item 3 (time 500.1 s): time jumps by"), std::string::npos)
        << what;
  }
}

TEST(LiveConversionTest, StoppingEarlyEndsTheConversionWithoutAReport) {
  test::ScratchFolder dir;
  WriteSequence(dir / "seq", 200);
  LiveConversion::QueueLimits limits;
  limits.max_scans = 2;
  auto live = std::make_unique<LiveConversion>("kitti", Input(dir / "seq"), limits);
  ASSERT_TRUE(live->NextScan().has_value());
  EXPECT_FALSE(live->report().has_value());  // still reading: the queues hold it back
  live.reset();                              // returns: the conversion stops at its next item
}

TEST(LiveConversionTest, ARecordingThatCannotBeOpenedThrowsAtOnce) {
  test::ScratchFolder dir;
  fs::create_directories(dir / "empty");
  EXPECT_THROW(DatasetReader("kitti", Input(dir / "empty")), InputError);
  EXPECT_THROW(DatasetReader("tape", Input(dir / "empty")), InputError);
}

}  // namespace
}  // namespace unimap::io
