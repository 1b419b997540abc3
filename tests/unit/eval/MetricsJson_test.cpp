#include "eval/MetricsJson.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

namespace unimap::eval {
namespace {

TrajectoryMetrics Sample() {
  TrajectoryMetrics m;
  m.ate_rmse_m = 0.1234567890123;
  m.path_length_m = 165.25;
  m.drift_percent = 1.34;
  m.max_abs_error_m = Eigen::Vector3d(2.0, 0.37, 1.11);
  m.mean_abs_rot_error_deg = Eigen::Vector3d(0.14, 0.15, 0.24);
  m.rot_drift_deg_per_m = 0.003;
  m.rpe_trans_percent = 1e-5;
  m.rpe_rot_deg_per_m = 2.5;
  m.rpe_segments = 17;
  m.poses_associated = 9000;
  m.poses_skipped = 3;
  m.poses_outside_truth_span = 2;
  m.poses_in_truth_gaps = 1;
  m.duration_s = 900.0;
  m.max_time_diff_s = 0.1;
  m.segment_m = 10.0;
  return m;
}

TEST(MetricsJsonTest, ParsesAndHasEveryKeyWithExactValues) {
  const YAML::Node json = YAML::Load(MetricsToJson(Sample()));
  ASSERT_TRUE(json.IsMap());
  for (const char* key :
       {"ate_rmse_m", "path_length_m", "drift_percent", "max_abs_error_m", "mean_abs_rot_error_deg",
        "rot_drift_deg_per_m", "rpe_trans_percent", "poses_associated", "poses_skipped", "duration_s"}) {
    EXPECT_TRUE(json[key].IsDefined()) << key;
  }
  const std::vector<std::string> keys = MetricsJsonKeys();
  EXPECT_EQ(json.size(), keys.size());
  for (const std::string& key : keys) EXPECT_TRUE(json[key].IsDefined()) << key;
  EXPECT_EQ(json["ate_rmse_m"].as<double>(), 0.1234567890123);  // round-trips bit-exactly
  EXPECT_EQ(json["rpe_trans_percent"].as<double>(), 1e-5);
  EXPECT_EQ(json["poses_associated"].as<int>(), 9000);
  ASSERT_TRUE(json["max_abs_error_m"].IsSequence());
  ASSERT_EQ(json["max_abs_error_m"].size(), 3u);
  EXPECT_EQ(json["max_abs_error_m"][1].as<double>(), 0.37);
  EXPECT_EQ(json["mean_abs_rot_error_deg"][2].as<double>(), 0.24);
}

TEST(MetricsJsonTest, UndefinedValuesAreNull) {
  TrajectoryMetrics m = Sample();
  m.drift_percent.reset();
  m.rpe_trans_percent.reset();
  const std::string text = MetricsToJson(m);
  EXPECT_NE(text.find("\"drift_percent\": null"), std::string::npos) << text;
  const YAML::Node json = YAML::Load(text);
  EXPECT_TRUE(json["rpe_trans_percent"].IsNull());
}

TEST(MetricsJsonTest, NonFiniteNumbersAreNull) {
  TrajectoryMetrics m = Sample();
  m.ate_rmse_m = std::nan("");
  m.max_abs_error_m.y() = std::numeric_limits<double>::infinity();
  const YAML::Node json = YAML::Load(MetricsToJson(m));
  EXPECT_TRUE(json["ate_rmse_m"].IsNull());
  EXPECT_TRUE(json["max_abs_error_m"][1].IsNull());
  EXPECT_EQ(json["max_abs_error_m"][0].as<double>(), 2.0);
}

}  // namespace
}  // namespace unimap::eval
