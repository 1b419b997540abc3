// End-to-end runs of the localiser on a short simulated tunnel, clean and
// with corrupted input: every corruption ends in a clear error or counted
// skips, never a crash, and the poses processed are kept.
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Localizer.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "PipelineTestData.hpp"
#include "Scenario.hpp"
#include "Simulator.hpp"
#include "io/DatasetReader.hpp"
#include "io/DatasetWriter.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Platform.hpp"

namespace unimap::pipeline {
namespace {

namespace fs = std::filesystem;
using test::CleanDataset;
using test::kPlatform;
using test::Scratch;

// Copies the clean dataset, letting `edit` change each event (return false to drop it).
fs::path RewriteDataset(const std::string& name, const std::function<bool(io::DatasetEvent*)>& edit) {
  const fs::path out = Scratch(name);
  fs::remove_all(out);
  io::DatasetReader reader(CleanDataset());
  io::DatasetWriter writer(out, reader.metadata());
  while (auto event = reader.NextEvent()) {
    if (!edit(&*event)) continue;
    if (auto* imu = std::get_if<ImuSample>(&*event)) writer.WriteImu(*imu);
    if (auto* enc = std::get_if<EncoderSample>(&*event)) writer.WriteEncoder(*enc);
    if (auto* scan = std::get_if<io::ScanRecord>(&*event)) writer.WriteScan(*scan);
  }
  io::DatasetReader truth(CleanDataset());
  while (auto pose = truth.NextGroundTruth()) writer.WriteGroundTruth(*pose);
  writer.Finish();
  return out;
}

struct Outcome {
  RunSummary summary;
  LocalizerStats stats;
  std::size_t trajectory_poses = 0;
};

Outcome Localize(const fs::path& data) {
  const Platform platform = LoadPlatform(kPlatform);
  Localizer localizer(LocalizerOptions::FromPlatform(CoreParameters::FromMap(platform.parameters)),
                      platform.plugin.plugin);
  io::DatasetReader reader(data);
  const fs::path trajectory_file = data / "estimate.tum";
  Outcome outcome;
  {
    io::TumTrajectoryWriter trajectory(trajectory_file);
    outcome.summary = RunDataset(reader, localizer, trajectory, RunOptions{});
  }
  outcome.stats = localizer.stats();
  outcome.trajectory_poses = io::ReadTumTrajectory(trajectory_file).size();
  return outcome;
}

TEST(RunDataset, CleanDataIsLocalizedWithoutSkips) {
  const Outcome o = Localize(CleanDataset());
  EXPECT_TRUE(o.summary.error.empty()) << o.summary.error;
  EXPECT_EQ(o.stats.scans, 240u);  // 6 s at 40 lines/s
  EXPECT_EQ(o.summary.poses_written, o.stats.scans);
  EXPECT_EQ(o.trajectory_poses, o.stats.scans);
  EXPECT_GT(o.stats.scans_matched, 150u);
  EXPECT_EQ(o.stats.scans_bad_input + o.stats.scans_no_encoder + o.stats.imu_gaps, 0u);
  // Static start in the tunnel: the estimate stays put.
  const auto poses = io::ReadTumTrajectory(CleanDataset() / "estimate.tum");
  EXPECT_LT(poses.back().T_map_body.translation().norm(), 0.1);
}

TEST(RunDataset, TruncatedScanFileEndsWithAnErrorKeepingThePoses) {
  const fs::path data = RewriteDataset("truncated", [](io::DatasetEvent*) { return true; });
  const auto size = fs::file_size(data / "scans.bin");
  fs::resize_file(data / "scans.bin", size - 1000);
  const Outcome o = Localize(data);
  EXPECT_NE(o.summary.error.find("scans.bin"), std::string::npos) << o.summary.error;
  EXPECT_NE(o.summary.error.find("truncated"), std::string::npos) << o.summary.error;
  EXPECT_GT(o.trajectory_poses, 100u);
  EXPECT_EQ(o.trajectory_poses, o.summary.poses_written);
}

TEST(RunDataset, NanRangesAreDroppedAndAllNanLinesSkipped) {
  int line = 0;
  const fs::path data = RewriteDataset("nan", [&line](io::DatasetEvent* e) {
    if (auto* scan = std::get_if<io::ScanRecord>(e)) {
      auto& ranges = std::get<LineScan>(*scan).ranges_m;
      ++line;
      if (line == 100) std::fill(ranges.begin(), ranges.end(), std::nanf(""));  // a line without returns
      if (line > 100 && line <= 110) ranges[line] = std::nanf("");              // single bad beams
    }
    return true;
  });
  const Outcome o = Localize(data);
  EXPECT_TRUE(o.summary.error.empty()) << o.summary.error;
  EXPECT_EQ(o.stats.scans_bad_input, 1u);
  EXPECT_GE(o.stats.beams_dropped, 10u + 1081u);
  EXPECT_EQ(o.summary.poses_written, o.stats.scans - 1);
}

TEST(RunDataset, ImuGapIsBridgedAndCounted) {
  const fs::path data = RewriteDataset("imu_gap", [](io::DatasetEvent* e) {
    const auto* imu = std::get_if<ImuSample>(e);
    return imu == nullptr || imu->time_s < 3.0 || imu->time_s > 3.5;
  });
  const Outcome o = Localize(data);
  EXPECT_TRUE(o.summary.error.empty()) << o.summary.error;
  EXPECT_EQ(o.stats.imu_gaps, 1u);
  EXPECT_EQ(o.summary.poses_written, o.stats.scans);
}

TEST(RunDataset, MissingEncoderSamplesSkipTheUncoveredScans) {
  const fs::path data = RewriteDataset("encoder_gap", [](io::DatasetEvent* e) {
    const auto* enc = std::get_if<EncoderSample>(e);
    return enc == nullptr || enc->time_s < 2.0 || enc->time_s > 3.0;
  });
  const Outcome o = Localize(data);
  EXPECT_TRUE(o.summary.error.empty()) << o.summary.error;
  const std::size_t skipped = o.stats.scans_no_encoder + o.stats.scans_bad_input;
  EXPECT_GE(skipped, 30u);  // about 40 lines fall in the 1 s gap
  EXPECT_LE(skipped, 42u);
  EXPECT_EQ(o.summary.poses_written + skipped, o.stats.scans);
  EXPECT_FALSE(o.stats.messages.empty());
}

TEST(RunDataset, ImuTimeGoingBackwardsInTheFileIsAnErrorNamingTheLine) {
  const fs::path data = RewriteDataset("imu_backwards", [](io::DatasetEvent*) { return true; });
  // Swap two IMU lines in the text file (the writer itself refuses this).
  std::ifstream in(data / "imu.csv");
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  in.close();
  std::swap(lines[400], lines[401]);
  std::ofstream out(data / "imu.csv");
  for (const auto& l : lines) out << l << '\n';
  out.close();
  const Outcome o = Localize(data);
  EXPECT_NE(o.summary.error.find("imu.csv:"), std::string::npos) << o.summary.error;
  EXPECT_GT(o.trajectory_poses, 0u);
}

}  // namespace
}  // namespace unimap::pipeline
