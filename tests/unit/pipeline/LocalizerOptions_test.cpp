#include "pipeline/LocalizerOptions.hpp"

#include <string>

#include <gtest/gtest.h>

#include "unimap/CoreParameters.hpp"

namespace unimap::pipeline {
namespace {

CoreParameters WithResolution(double resolution_m) {
  CoreParameters core;
  core.scans_per_3d_scan = 40;
  core.sigma_accel_m_s2 = 0.03;
  core.distance_map_resolution_m = resolution_m;
  core.distance_map_max_range_m = 15.0;
  return core;
}

TEST(LocalizerOptionsTest, FromPlatformTakesThePlatformsValues) {
  const LocalizerOptions o = LocalizerOptions::FromPlatform(WithResolution(0.3));
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
  EXPECT_EQ(o.scans_per_3d_scan, 40);
  EXPECT_DOUBLE_EQ(o.eskf.sigma_accel_m_s2, 0.03);
  EXPECT_DOUBLE_EQ(o.map.resolution_m, 0.3);
  EXPECT_DOUBLE_EQ(o.gpf.voxel_size_m, 0.3);
  EXPECT_DOUBLE_EQ(o.map.max_range_m, 15.0);
  EXPECT_FALSE(o.localize_only);
  // Odometry: unsigned distances to the surfaces inside the voxels.
  EXPECT_TRUE(o.map.subvoxel_surfaces);
  EXPECT_FALSE(o.map.signed_surfaces);
}

TEST(LocalizerOptionsTest, OdometryClampsTheDistanceMapWhereTheParticleFilterDoes) {
  const LocalizerOptions fine = LocalizerOptions::FromPlatform(WithResolution(0.1));
  EXPECT_DOUBLE_EQ(fine.map.clamp_distance_m, fine.gpf.clamp_distance_m);
  EXPECT_DOUBLE_EQ(fine.map.clamp_distance_m, 0.5);
  // Never below one voxel (DistanceMapOptions::IsValid).
  const LocalizerOptions coarse = LocalizerOptions::FromPlatform(WithResolution(0.8));
  EXPECT_DOUBLE_EQ(coarse.map.clamp_distance_m, 0.8);
  std::string why;
  EXPECT_TRUE(coarse.IsValid(&why)) << why;
  // A prior map keeps the default; unimap localize sets its own.
  EXPECT_DOUBLE_EQ(LocalizerOptions::ForPriorMap(WithResolution(0.1)).map.clamp_distance_m,
                   map::DistanceMapOptions{}.clamp_distance_m);
}

TEST(LocalizerOptionsTest, ForPriorMapCapsACoarsePlatformResolution) {
  const LocalizerOptions o = LocalizerOptions::ForPriorMap(WithResolution(0.3));
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
  EXPECT_DOUBLE_EQ(o.map.resolution_m, LocalizerOptions::kPriorMapResolutionM);
  EXPECT_DOUBLE_EQ(o.gpf.voxel_size_m, LocalizerOptions::kPriorMapResolutionM);
  // The platform's other values are kept.
  EXPECT_EQ(o.scans_per_3d_scan, 40);
  EXPECT_DOUBLE_EQ(o.eskf.sigma_accel_m_s2, 0.03);
  EXPECT_DOUBLE_EQ(o.map.max_range_m, 15.0);
}

TEST(LocalizerOptionsTest, ForPriorMapKeepsAFinerPlatformResolution) {
  const LocalizerOptions o = LocalizerOptions::ForPriorMap(WithResolution(0.05));
  EXPECT_DOUBLE_EQ(o.map.resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(o.gpf.voxel_size_m, 0.05);
}

TEST(LocalizerOptionsTest, ForPriorMapTunesForAFixedMap) {
  const LocalizerOptions odometry = LocalizerOptions::FromPlatform(WithResolution(0.1));
  const LocalizerOptions prior = LocalizerOptions::ForPriorMap(WithResolution(0.1));
  EXPECT_TRUE(prior.localize_only);
  EXPECT_TRUE(prior.map.subvoxel_surfaces);
  EXPECT_TRUE(prior.map.signed_surfaces);
  EXPECT_EQ(prior.gpf.refine_iterations, 0);
  EXPECT_GT(odometry.gpf.refine_iterations, 0);
  // Wider particles than odometry's.
  EXPECT_GT(prior.gpf.min_sigma_position_m, odometry.gpf.min_sigma_position_m);
  EXPECT_GT(prior.gpf.min_sigma_rotation_rad, odometry.gpf.min_sigma_rotation_rad);
  // The simulated IMU's bias walks, twice odometry's.
  EXPECT_DOUBLE_EQ(prior.eskf.accel_bias_walk_m_s2_sqrt_s, 2e-4);
  EXPECT_DOUBLE_EQ(prior.eskf.gyro_bias_walk_rad_s_sqrt_s, 2e-5);
  EXPECT_DOUBLE_EQ(prior.eskf.accel_bias_walk_m_s2_sqrt_s, 2.0 * odometry.eskf.accel_bias_walk_m_s2_sqrt_s);
  EXPECT_DOUBLE_EQ(prior.eskf.gyro_bias_walk_rad_s_sqrt_s, 2.0 * odometry.eskf.gyro_bias_walk_rad_s_sqrt_s);
}

TEST(LocalizerOptionsTest, PlaneMatchingTiesPointsToNeighborhoodPlanesOnly) {
  LocalizerOptions o = LocalizerOptions::FromPlatform(WithResolution(0.1));
  EXPECT_FALSE(o.neighborhood_planes.has_value());  // off unless asked for (unimap run --plane-matching)
  EXPECT_FALSE(o.gpf.point_to_plane);
  o.UsePlaneMatching();
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
  EXPECT_TRUE(o.neighborhood_planes.has_value());
  EXPECT_TRUE(o.gpf.point_to_plane);
  EXPECT_TRUE(o.gpf.planes_only);
  EXPECT_FALSE(o.line_gap_fill.has_value());  // planes are fitted across the measured stripes
  // Neighbourhood planes without point to plane would never be used.
  o.gpf.point_to_plane = false;
  o.gpf.planes_only = false;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("neighborhood_planes"), std::string::npos);
  o.UsePlaneMatching();
  o.neighborhood_planes->radius_cells = 0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("neighborhood_plane: radius_cells"), std::string::npos);
}

TEST(LocalizerOptionsTest, LineGapFillIsOnByDefaultAndChecked) {
  LocalizerOptions o = LocalizerOptions::FromPlatform(WithResolution(0.1));
  ASSERT_TRUE(o.line_gap_fill.has_value());
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
  o.line_gap_fill->max_incidence_deg = 95.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("line_gap_fill: max_incidence_deg"), std::string::npos);
  o.line_gap_fill.reset();  // off (unimap run --no-line-gap-fill)
  EXPECT_TRUE(o.IsValid(&why)) << why;
}

TEST(LocalizerOptionsTest, LinePointsAreGatedAtOneAndAHalfVoxelsExceptInAPriorMap) {
  LocalizerOptions o = LocalizerOptions::FromPlatform(WithResolution(0.1));
  EXPECT_NEAR(o.max_predicted_distance_m, 0.15, 1e-12);
  EXPECT_NEAR(LocalizerOptions::FromPlatform(WithResolution(0.3)).max_predicted_distance_m, 0.45, 1e-12);
  // A complete prior map: every point is measured.
  EXPECT_EQ(LocalizerOptions::ForPriorMap(WithResolution(0.1)).max_predicted_distance_m, 0.0);
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
  o.max_predicted_distance_m = -0.1;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("max_predicted_distance_m"), std::string::npos);
}

}  // namespace
}  // namespace unimap::pipeline
