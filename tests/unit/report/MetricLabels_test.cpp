#include "report/MetricLabels.hpp"

#include <gtest/gtest.h>

namespace unimap::report {
namespace {

TEST(MetricLabelsTest, KnownKeysHaveTheirNames) {
  EXPECT_EQ(LabelFor("ate_rmse_m").label, "ATE RMSE (SE(3)-aligned)");
  EXPECT_EQ(LabelFor("ate_rmse_m").unit, "m");
  EXPECT_EQ(LabelFor("peak_rss_mb").unit, "MiB");
  EXPECT_EQ(LabelFor("realtime_factor").unit, "x");
}

TEST(MetricLabelsTest, OtherKeysAreNamedAfterThemselvesWithTheirUnitSuffix) {
  EXPECT_EQ(LabelFor("map_entropy_mean_m").label, "Map entropy mean");
  EXPECT_EQ(LabelFor("map_entropy_mean_m").unit, "m");
  EXPECT_EQ(LabelFor("rpe_rot_deg_per_m").unit, "deg/m");  // not "m"
  EXPECT_EQ(LabelFor("stage_matching_s").label, "Stage matching");
  EXPECT_EQ(LabelFor("stage_matching_s").unit, "s");
  EXPECT_EQ(LabelFor("loop_closures").label, "Loop closures");
  EXPECT_EQ(LabelFor("loop_closures").unit, "");
  EXPECT_EQ(LabelFor("scans").unit, "");
}

TEST(MetricLabelsTest, DottedKeysUseTheirLastPartWhenKnown) {
  EXPECT_EQ(LabelFor("mapping.optimisations").label, "Pose-graph optimisations");
  EXPECT_EQ(LabelFor("odometry.height_error_m").label, "Odometry height error");
  EXPECT_EQ(LabelFor("odometry.height_error_m").unit, "m");
}

}  // namespace
}  // namespace unimap::report
