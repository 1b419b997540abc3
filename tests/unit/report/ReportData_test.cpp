#include "report/ReportData.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "ReportFixtures.hpp"
#include "report/LoopClosureLayer.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {
namespace {

using testing::RunFolderTest;

TEST_F(RunFolderTest, HoldsThePlotsTrajectoriesAndABudgetOfTheMap) {
  WriteRun(50, 1000);
  std::ofstream(dir_ / "run" / "loop_closures.csv") << "# header\n1.0 0 0 1 2 0 1\n2.0 1 0 1 3 0 1\n";
  ReportOptions options;
  options.folder = dir_ / "run";
  options.map_point_budget = 300;                                                       // every 4th point: 250
  options.surface_distance = [](const Eigen::Vector3d& p) { return std::abs(p.z()); };  // the floor
  const ReportData data = BuildReportData(ResolveRunFolder(options), options);
  EXPECT_EQ(data.counts.estimate_poses, 50u);
  EXPECT_EQ(data.counts.truth_pairs, 50u);
  EXPECT_EQ(data.counts.plots, 3u);
  EXPECT_EQ(data.counts.plot_rows, 50u);
  EXPECT_EQ(data.counts.map.total, 1000u);
  EXPECT_EQ(data.counts.map.shown, 250u);
  EXPECT_TRUE(data.counts.map.error);
  EXPECT_FALSE(data.counts.map.intensity);
  EXPECT_EQ(data.counts.loop_closures, 2u);

  const nlohmann::ordered_json& p = data.payload;
  EXPECT_EQ(p["title"], "unimap run: rotating_2d on " + dir_.filename().string() + "/data");
  EXPECT_EQ(p["map"]["shown"], 250u);
  ASSERT_EQ(p["trajectories"].size(), 2u);  // estimate, truth
  EXPECT_EQ(p["trajectories"][1]["name"], "truth");
  ASSERT_EQ(p["plots"].size(), 3u);
  EXPECT_EQ(p["plots"][0]["id"], "position");
  EXPECT_EQ(p["plots"][0]["labels"].size(), 7u);
  EXPECT_EQ(p["plots"][1]["id"], "position_error");
  EXPECT_EQ(p["cards"][1]["key"], "realtime_factor");
  EXPECT_FALSE(p["metrics"].empty());  // computed: the folder has no metrics.json
}

TEST_F(RunFolderTest, WithoutTruthPlotsThePositionOnly) {
  WriteRun(30, 10);
  ReportOptions options;
  options.folder = dir_ / "run";
  options.truth_file.clear();
  std::filesystem::remove(dir_ / "data" / "groundtruth.tum");
  options.plot_row_budget = 10;  // every 3rd pose
  const ReportData data = BuildReportData(ResolveRunFolder(options), options);
  EXPECT_EQ(data.counts.truth_pairs, 0u);
  EXPECT_EQ(data.counts.plots, 1u);
  EXPECT_EQ(data.counts.plot_rows, 10u);
  EXPECT_FALSE(data.counts.map.error);
  EXPECT_EQ(data.payload["map"]["error_note"], "no true world (simulated data only)");
  EXPECT_EQ(data.payload["trajectories"][0]["count"], 10u);
}

TEST_F(RunFolderTest, ATruthThatDoesNotOverlapIsANote) {
  WriteRun(20, 10);
  std::vector<StampedPose> later = testing::Line(20, 0.0);
  for (StampedPose& p : later) p.time_s += 1000.0;
  io::WriteTumTrajectory(dir_ / "data" / "groundtruth.tum", later);
  ReportOptions options;
  options.folder = dir_ / "run";
  const ReportData data = BuildReportData(ResolveRunFolder(options), options);
  EXPECT_EQ(data.counts.truth_pairs, 0u);
  ASSERT_EQ(data.payload["notes"].size(), 1u);
  EXPECT_NE(data.payload["notes"][0].get<std::string>().find("Not evaluated"), std::string::npos);
}

TEST_F(RunFolderTest, AMapWithIntensitiesCanBeColoredByThem) {
  {
    std::ofstream pcd(dir_ / "cloud.pcd");
    pcd << "VERSION .7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 1\n"
           "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n0 0 0 5\n1 0 0 7\nnan 0 0 9\n";
  }
  MapLayerCounts counts;
  const nlohmann::ordered_json layer = MapLayer(dir_ / "cloud.pcd", 100, std::nullopt, {}, &counts);
  EXPECT_EQ(counts.total, 2u);  // the non-finite point dropped
  EXPECT_TRUE(counts.intensity);
  EXPECT_EQ(layer["intensity"], "AACgQAAA4EA=");  // 5.0f, 7.0f
  EXPECT_TRUE(layer["error"].is_null());
  EXPECT_EQ(layer["error_note"], "no true world (simulated data only)");
}

TEST_F(RunFolderTest, AMalformedLoopClosureLineNamesFileAndLine) {
  std::ofstream(dir_ / "loops.csv") << "# header\n1 2 3\n";
  try {
    LoopClosureLayer(dir_ / "loops.csv", nullptr);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loops.csv:2:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unimap::report
