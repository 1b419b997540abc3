#include "eval/EvaluationReport.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include "EvalFixtures.hpp"
#include "PngTestSupport.hpp"
#include "eval/MetricRows.hpp"
#include "eval/MetricsJson.hpp"

namespace unimap::eval {
namespace {

std::string ReadAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::size_t CountOccurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

class EvaluationReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("unimap_eval_report_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(EvaluationReportTest, WritesJsonPngsAndASelfContainedHtml) {
  // Helix with a growing z error, so every plot has something to show.
  const std::vector<StampedPose> truth = testing::Helix();
  std::vector<StampedPose> estimate = truth;
  for (std::size_t k = 0; k < estimate.size(); ++k) {
    estimate[k].T_map_body.translation().z() += 0.001 * static_cast<double>(k);
  }
  const TrajectoryEvaluation ev = EvaluateTrajectory(estimate, truth);
  const std::vector<std::filesystem::path> written =
      WriteEvaluationReport(ev, {"est <a>.tum", "gt.tum"}, dir_ / "out");
  ASSERT_EQ(written.size(), 6u);
  for (const auto& file : written) EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out")) {
    EXPECT_EQ(entry.path().extension().string().find("partial"), std::string::npos) << entry.path();
  }

  // metrics.json: JSON is YAML; every key, same numbers.
  const YAML::Node json = YAML::LoadFile((dir_ / "out" / "metrics.json").string());
  for (const std::string& key : MetricsJsonKeys()) EXPECT_TRUE(json[key].IsDefined()) << key;
  EXPECT_EQ(json["ate_rmse_m"].as<double>(), ev.metrics.ate_rmse_m);
  EXPECT_EQ(json["max_abs_error_m"][2].as<double>(), ev.metrics.max_abs_error_m.z());

  // PNGs: signature and IHDR size.
  const std::pair<const char*, std::uint32_t> pngs[] = {{"trajectory_top.png", 800},
                                                        {"trajectory_side.png", 500},
                                                        {"position_error.png", 990},
                                                        {"rotation_error.png", 990}};
  for (const auto& [name, height] : pngs) {
    const std::string png = ReadAll(dir_ / "out" / name);
    ASSERT_TRUE(testing::HasPngSignatureAndIhdr(png)) << name;
    EXPECT_EQ(testing::PngWidth(png), 1000u) << name;
    EXPECT_EQ(testing::PngHeight(png), height) << name;
  }

  // HTML: every metric row, 4 embedded pictures, escaped sources, nothing external.
  const std::string html = ReadAll(dir_ / "out" / "report.html");
  for (const MetricRow& row : DescribeMetrics(ev.metrics)) {
    EXPECT_NE(html.find("<code>" + row.key + "</code></td><td class=\"v\">" + row.value), std::string::npos)
        << row.key;
  }
  EXPECT_EQ(CountOccurrences(html, "src=\"data:image/png;base64,"), 4u);
  EXPECT_EQ(CountOccurrences(html, "src=\"http"), 0u);
  EXPECT_NE(html.find("est &lt;a&gt;.tum"), std::string::npos);
}

TEST_F(EvaluationReportTest, OverwritesAnEarlierReport) {
  const TrajectoryEvaluation ev = EvaluateTrajectory(testing::StraightLine(20), testing::StraightLine(20));
  WriteEvaluationReport(ev, {"a", "b"}, dir_);
  const std::vector<std::filesystem::path> written = WriteEvaluationReport(ev, {"c", "d"}, dir_);
  EXPECT_NE(ReadAll(written.back()).find("<code>c</code>"), std::string::npos);
}

}  // namespace
}  // namespace unimap::eval
