#include "report/RunFolder.hpp"

#include <gtest/gtest.h>

#include "ReportFixtures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {
namespace {

using testing::RunFolderTest;

TEST_F(RunFolderTest, FindsTheRunsFilesAndTheDatasetsTruth) {
  WriteRun(20, 10);
  ReportOptions options;
  options.folder = dir_ / "run";
  const RunFolder f = ResolveRunFolder(options);
  EXPECT_EQ(f.estimate_file, dir_ / "run" / "trajectory.tum");
  EXPECT_EQ(f.truth_file, dir_ / "data" / "groundtruth.tum");
  EXPECT_EQ(f.map_file, dir_ / "run" / "map.ply");
  EXPECT_TRUE(f.odometry_file.empty());
  EXPECT_TRUE(f.loops_file.empty());
  EXPECT_EQ(f.run["payload"], "rotating_2d");
  EXPECT_TRUE(f.metrics.empty());
  EXPECT_TRUE(f.notes.empty());
}

TEST_F(RunFolderTest, WithoutTruthSaysSo) {
  WriteRun(20, 10);
  std::filesystem::remove(dir_ / "data" / "groundtruth.tum");
  ReportOptions options;
  options.folder = dir_ / "run";
  const RunFolder f = ResolveRunFolder(options);
  EXPECT_TRUE(f.truth_file.empty());
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_NE(f.notes[0].find("groundtruth.tum does not exist"), std::string::npos);
}

TEST_F(RunFolderTest, ErrorsNameTheFile) {
  WriteRun(20, 10);
  ReportOptions options;
  options.folder = dir_ / "run";
  options.map_file = dir_ / "nope.pcd";
  EXPECT_THROW(ResolveRunFolder(options), InputError);
  options.map_file.clear();
  std::ofstream(dir_ / "run" / "run.json") << "{\"payload\": ";
  try {
    ResolveRunFolder(options);
    FAIL() << "no error for a truncated run.json";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.json: not valid JSON"), std::string::npos) << e.what();
  }
  options.folder = dir_ / "data";  // neither a trajectory nor a map
  std::filesystem::remove(dir_ / "data" / "groundtruth.tum");
  EXPECT_THROW(ResolveRunFolder(options), InputError);
  options.folder = dir_ / "missing";
  EXPECT_THROW(ResolveRunFolder(options), InputError);
}

}  // namespace
}  // namespace unimap::report
