#include "unimap/CoreParameters.hpp"

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

TEST(CoreParameters, RoundTripsThroughParameterSet) {
  CoreParameters p;
  p.scans_per_3d_scan = 40;
  p.distance_map_resolution_m = 0.05;
  ParameterSet set;
  p.AddTo(&set);
  std::string why;
  ASSERT_TRUE(set.IsValid(&why)) << why;
  ASSERT_EQ(set.specs().size(), CoreParameters::Keys().size());
  for (const auto& key : CoreParameters::Keys()) EXPECT_NE(set.Find(key), nullptr) << key;
  EXPECT_EQ(set.Find("scans_per_3d_scan")->symbol, "N");
  const CoreParameters back = CoreParameters::FromMap(set.DefaultMap());
  EXPECT_EQ(back.scans_per_3d_scan, 40);
  EXPECT_DOUBLE_EQ(back.distance_map_resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(back.sigma_gyro_rad_s, p.sigma_gyro_rad_s);
}

TEST(CoreParameters, InconsistentValuesAreRejected) {
  CoreParameters p;
  p.distance_map_resolution_m = 10.0;
  p.distance_map_max_range_m = 20.0;
  std::string why;
  EXPECT_FALSE(p.IsValid(&why));
  ParameterSet set;
  CoreParameters{}.AddTo(&set);
  ParameterMap map = set.DefaultMap();
  map.Set("scans_per_3d_scan", std::int64_t{0});
  EXPECT_THROW(CoreParameters::FromMap(map), ConfigError);
  map = set.DefaultMap();
  map.Set("distance_map_resolution_m", 10.0);
  EXPECT_THROW(CoreParameters::FromMap(map), ConfigError);
}

}  // namespace
}  // namespace unimap
