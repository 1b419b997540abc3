#include "eval/EvaluationReport.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include "EvalFixtures.hpp"
#include "PngTestSupport.hpp"
#include "eval/MetricsJson.hpp"

namespace unimap::eval {
namespace {

std::string ReadAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class EvaluationReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) / ("unimap_eval_report_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(EvaluationReportTest, WritesJsonAndPngs) {
  // Helix with a growing z error, so every plot has something to show.
  const std::vector<StampedPose> truth = testing::Helix();
  std::vector<StampedPose> estimate = truth;
  for (std::size_t k = 0; k < estimate.size(); ++k) {
    estimate[k].T_map_body.translation().z() += 0.001 * static_cast<double>(k);
  }
  const TrajectoryEvaluation ev = EvaluateTrajectory(estimate, truth);
  const std::vector<std::filesystem::path> written = WriteEvaluationReport(ev, dir_ / "out");
  ASSERT_EQ(written.size(), 5u);
  for (const auto& file : written) EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out")) {
    EXPECT_EQ(entry.path().extension().string().find("partial"), std::string::npos) << entry.path();
  }

  // metrics.json: JSON is YAML; every key, same numbers.
  const YAML::Node json = YAML::LoadFile((dir_ / "out" / "metrics.json").string());
  for (const std::string& key : MetricsJsonKeys()) EXPECT_TRUE(json[key].IsDefined()) << key;
  EXPECT_EQ(json["ate_rmse_m"].as<double>(), ev.metrics.ate_rmse_m);
  EXPECT_EQ(json["max_abs_error_m"][2].as<double>(), ev.metrics.max_abs_error_m.z());

  // PNGs: signature and IHDR size; the trajectory views as high as the
  // helix (a circle seen from above, a flat band from the side) needs.
  for (const char* name : {"trajectory_top.png", "trajectory_side.png", "position_error.png", "rotation_error.png"}) {
    const std::string png = ReadAll(dir_ / "out" / name);
    ASSERT_TRUE(testing::HasPngSignatureAndIhdr(png)) << name;
    EXPECT_EQ(testing::PngWidth(png), 1000u) << name;
  }
  EXPECT_EQ(testing::PngHeight(ReadAll(dir_ / "out" / "position_error.png")), 900u);
  const std::uint32_t top = testing::PngHeight(ReadAll(dir_ / "out" / "trajectory_top.png"));
  const std::uint32_t side = testing::PngHeight(ReadAll(dir_ / "out" / "trajectory_side.png"));
  EXPECT_GT(top, side);
  EXPECT_GE(side, 320u);
  EXPECT_LE(top, 900u);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "report.html"));
}

TEST_F(EvaluationReportTest, OverwritesEarlierFiles) {
  const TrajectoryEvaluation ev = EvaluateTrajectory(testing::StraightLine(20), testing::StraightLine(20));
  std::filesystem::create_directories(dir_);
  std::ofstream(dir_ / "metrics.json") << "old";
  const std::vector<std::filesystem::path> written = WriteEvaluationReport(ev, dir_);
  EXPECT_EQ(ReadAll(written.front()).rfind("{\n", 0), 0u);
}

}  // namespace
}  // namespace unimap::eval
