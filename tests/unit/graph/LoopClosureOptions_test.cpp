#include "graph/LoopClosureOptions.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::graph {
namespace {

TEST(LoopClosureOptionsTest, DefaultsAreValid) {
  std::string why = "untouched";
  EXPECT_TRUE(LoopClosureOptions{}.IsValid(&why));
  EXPECT_EQ(why, "untouched");
  EXPECT_TRUE(LoopClosureOptions{}.IsValid(nullptr));
}

TEST(LoopClosureOptionsTest, EachBadValueIsCaughtWithAReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(LoopClosureOptions&)>>> cases = {
      {"zero search resolution", [](LoopClosureOptions& o) { o.search_resolution_m = 0.0; }},
      {"NaN kernel", [nan](LoopClosureOptions& o) { o.search_kernel_m = nan; }},
      {"kernel of 20 cells", [](LoopClosureOptions& o) { o.search_kernel_m = 20.0 * o.search_resolution_m; }},
      {"no search level", [](LoopClosureOptions& o) { o.search_levels = 0; }},
      {"9 search levels", [](LoopClosureOptions& o) { o.search_levels = 9; }},
      {"negative fine resolution", [](LoopClosureOptions& o) { o.fine_resolution_m = -0.1; }},
      {"clamp below resolution", [](LoopClosureOptions& o) { o.fine_clamp_m = 0.05; }},
      {"clamp of 20 cells", [](LoopClosureOptions& o) { o.fine_clamp_m = 2.0; }},
      {"zero normal cell", [](LoopClosureOptions& o) { o.normal_cell_m = 0.0; }},
      {"planarity above 1", [](LoopClosureOptions& o) { o.planarity_ratio = 1.5; }},
      {"negative search voxel", [](LoopClosureOptions& o) { o.search_voxel_m = -1.0; }},
      {"5 search points", [](LoopClosureOptions& o) { o.max_search_points = 5; }},
      {"min points above max", [](LoopClosureOptions& o) { o.min_scan_points = o.max_refine_points + 1; }},
      {"negative z window", [](LoopClosureOptions& o) { o.z_window_m = -0.1; }},
      {"yaw window above pi", [](LoopClosureOptions& o) { o.yaw_window_rad = 4.0; }},
      {"min yaw step above max", [](LoopClosureOptions& o) { o.min_yaw_step_rad = 0.1; }},
      {"infinite margin",
       [](LoopClosureOptions& o) { o.ambiguity_margin_m = std::numeric_limits<double>::infinity(); }},
      {"one candidate", [](LoopClosureOptions& o) { o.max_candidates = 1; }},
      {"search score above 1", [](LoopClosureOptions& o) { o.min_search_score = 1.2; }},
      {"negative score ratio", [](LoopClosureOptions& o) { o.candidate_score_ratio = -0.1; }},
      {"no iteration", [](LoopClosureOptions& o) { o.max_iterations = 0; }},
      {"zero Huber", [](LoopClosureOptions& o) { o.huber_m = 0.0; }},
      {"inlier distance above clamp", [](LoopClosureOptions& o) { o.inlier_distance_m = 0.5; }},
      {"min score above 1", [](LoopClosureOptions& o) { o.min_score = 1.1; }},
      {"NaN max ambiguity", [nan](LoopClosureOptions& o) { o.max_ambiguity = nan; }},
      {"zero ambiguity floor", [](LoopClosureOptions& o) { o.ambiguity_floor = 0.0; }},
      {"zero distinct translation", [](LoopClosureOptions& o) { o.distinct_translation_m = 0.0; }},
      {"zero distinct rotation", [](LoopClosureOptions& o) { o.distinct_rotation_rad = 0.0; }},
      {"zero position sigma bound", [](LoopClosureOptions& o) { o.max_position_sigma_m = 0.0; }},
      {"negative rotation sigma bound", [](LoopClosureOptions& o) { o.max_rotation_sigma_rad = -1.0; }},
      {"zero effective points", [](LoopClosureOptions& o) { o.effective_points = 0.0; }},
      {"negative sigma floor", [](LoopClosureOptions& o) { o.min_sigma_position_m = -0.01; }},
  };
  for (const auto& [name, mutate] : cases) {
    LoopClosureOptions options;
    mutate(options);
    std::string why;
    EXPECT_FALSE(options.IsValid(&why)) << name;
    EXPECT_FALSE(why.empty()) << name;
    EXPECT_FALSE(options.IsValid(nullptr)) << name;
  }
}

}  // namespace
}  // namespace unimap::graph
