#include "map/DistanceMapOptions.hpp"

#include <functional>
#include <limits>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

TEST(DistanceMapOptions, DefaultsAreValid) {
  std::string why = "untouched";
  EXPECT_TRUE(DistanceMapOptions{}.IsValid(&why));
  EXPECT_EQ(why, "untouched");
  EXPECT_TRUE(DistanceMapOptions{}.IsValid(nullptr));
}

TEST(DistanceMapOptions, EachOutOfRangeFieldIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::string, std::function<void(DistanceMapOptions&)>>> cases = {
      {"resolution_m", [](DistanceMapOptions& o) { o.resolution_m = 0.0; }},
      {"resolution_m", [nan](DistanceMapOptions& o) { o.resolution_m = nan; }},
      {"max_range_m", [](DistanceMapOptions& o) { o.max_range_m = 0.15; }},
      {"clamp_distance_m", [](DistanceMapOptions& o) { o.clamp_distance_m = 0.05; }},
      {"clamp_distance_m", [](DistanceMapOptions& o) { o.clamp_distance_m = 20.0; }},
      {"recenter_fraction", [](DistanceMapOptions& o) { o.recenter_fraction = 0.0; }},
      {"recenter_fraction", [](DistanceMapOptions& o) { o.recenter_fraction = 1.5; }},
      {"growth_margin_m", [](DistanceMapOptions& o) { o.growth_margin_m = -1.0; }},
      {"max_edt_cells", [](DistanceMapOptions& o) { o.max_edt_cells = 10; }},
      {"max_occupied_voxels", [](DistanceMapOptions& o) { o.max_occupied_voxels = 0; }},
      {"max_insert_range_m", [](DistanceMapOptions& o) { o.max_insert_range_m = -3.0; }},
      {"prob_hit", [](DistanceMapOptions& o) { o.prob_hit = 0.4; }},
      {"prob_miss", [](DistanceMapOptions& o) { o.prob_miss = 0.6; }},
      {"occupancy_threshold", [](DistanceMapOptions& o) { o.occupancy_threshold = 0.99; }},
      {"clamp_min_probability", [](DistanceMapOptions& o) { o.clamp_min_probability = 0.0; }},
      {"key range",
       [](DistanceMapOptions& o) {
         o.resolution_m = 0.001;
         o.max_range_m = 10.0;
         o.clamp_distance_m = 1.0;
       }},
  };
  for (const auto& [field, breaks] : cases) {
    DistanceMapOptions options;
    breaks(options);
    std::string why;
    EXPECT_FALSE(options.IsValid(&why)) << field;
    EXPECT_NE(why.find(field), std::string::npos) << field << ": " << why;
    EXPECT_FALSE(options.IsValid(nullptr));
  }
}

}  // namespace
}  // namespace unimap::map
