#include "pipeline/MapperSettings.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PipelineTestData.hpp"
#include "options/SettingsOverrides.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"

namespace unimap::pipeline {
namespace {

// The shipped rotating Hokuyo platform file (21 lines) followed by extra.
Platform WithSettings(const std::string& extra) {
  std::ifstream in(test::kPlatform);
  std::stringstream text;
  text << in.rdbuf() << extra;
  return LoadPlatformFromString(text.str(), "platform.yaml");
}

// The line extra's first line gets in WithSettings.
int FirstExtraLine() {
  std::ifstream in(test::kPlatform);
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) ++lines;
  return lines + 1;
}

// The ConfigError MapperOptionsFor throws for the platform with extra (a
// failure if none).
ConfigError SettingsError(const std::string& extra) {
  try {
    MapperOptionsFor(WithSettings(extra));
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << extra;
  return ConfigError("", 0, "", "");
}

// Every field of options as `unimap config` lists it.
std::vector<std::string> Rows(MapperOptions options) {
  std::vector<std::string> rows;
  for (const options::FieldRow& row : options::ListFields([&](options::FieldVisitor& v) { options.VisitFields(v); })) {
    rows.push_back(row.key + "=" + row.value);
  }
  return rows;
}

TEST(MapperSettingsTest, WithoutASectionTheOptionsAreFromPlatforms) {
  const Platform platform = WithSettings("");
  EXPECT_EQ(Rows(MapperOptionsFor(platform)),
            Rows(MapperOptions::FromPlatform(CoreParameters::FromMap(platform.parameters))));
}

TEST(MapperSettingsTest, EverySectionReachesItsStruct) {
  const MapperOptions o =
      MapperOptionsFor(WithSettings("mapper:\n"
                                    "  eskf: {accel_bias_walk_m_s2_sqrt_s: 0.0002}\n"
                                    "  motion: {velocity_sigma_m_s: 2}\n"
                                    "  gpf: {num_particles: 250, planar: true}\n"
                                    "  map: {prob_hit: 0.8, max_insert_range_m: 25}\n"
                                    "  reacquire: {coarse_factor: 3}\n"
                                    "  line_gap_fill: {max_gap_m: 0.5}\n"
                                    "  graph: {max_iterations: 7}\n"
                                    "  loop_closure: {min_score: 0.7, seed: 9}\n"
                                    "  loop_search: {enabled: false, max_radius_m: 3}\n"
                                    "  min_points_to_match: 50\n"
                                    "  scan_sigma_position_m: 0.2\n"));
  EXPECT_EQ(o.localizer.eskf.accel_bias_walk_m_s2_sqrt_s, 0.0002);
  EXPECT_EQ(o.localizer.motion.velocity_sigma_m_s, 2.0);
  EXPECT_EQ(o.localizer.gpf.num_particles, 250);
  EXPECT_TRUE(o.localizer.gpf.planar);
  EXPECT_EQ(o.localizer.map.prob_hit, 0.8);
  EXPECT_EQ(o.localizer.map.max_insert_range_m, 25.0);
  EXPECT_EQ(o.submaps.map.prob_hit, 0.8);  // each submap's map is the `map` section
  EXPECT_EQ(o.localizer.reacquire.coarse_factor, 3);
  ASSERT_TRUE(o.localizer.line_gap_fill.has_value());
  EXPECT_EQ(o.localizer.line_gap_fill->max_gap_m, 0.5);
  EXPECT_EQ(o.graph.max_iterations, 7);
  EXPECT_EQ(o.loop_closure.min_score, 0.7);
  EXPECT_EQ(o.loop_closure.seed, 9u);
  EXPECT_FALSE(o.loop_search.enabled);
  EXPECT_EQ(o.loop_search.max_radius_m, 3.0);
  EXPECT_EQ(o.localizer.min_points_to_match, 50);
  EXPECT_EQ(o.scan_sigma_position_m, 0.2);
}

TEST(MapperSettingsTest, DerivedValuesFollowUnlessSetThemselves) {
  MapperOptions o = MapperOptionsFor(WithSettings("mapper:\n  gpf:\n    clamp_distance_m: 0.8\n"));
  EXPECT_EQ(o.localizer.map.clamp_distance_m, 0.8);  // the field is exact as far as the likelihood reads
  EXPECT_EQ(o.submaps.map.clamp_distance_m, 0.8);
  o = MapperOptionsFor(WithSettings("mapper:\n  gpf:\n    clamp_distance_m: 0.8\n  map:\n    clamp_distance_m: 1.2\n"));
  EXPECT_EQ(o.localizer.map.clamp_distance_m, 1.2);
  EXPECT_FALSE(MapperOptionsFor(WithSettings("mapper:\n  line_gap_fill:\n    enabled: false\n"))
                   .localizer.line_gap_fill.has_value());
}

// One section: a key it does not have and a value its options reject are
// errors naming the platform file, the line and the full key.
struct SectionCase {
  const char* section;
  const char* out_of_range;  // key: value that IsValid rejects
};

class MapperSettingsSectionTest : public ::testing::TestWithParam<SectionCase> {};

TEST_P(MapperSettingsSectionTest, UnknownAndOutOfRangeKeysNameFileLineAndKey) {
  const SectionCase c = GetParam();
  const std::string section = c.section;
  const std::string indent = section.empty() ? "  " : "    ";
  const std::string head = section.empty() ? "mapper:\n" : "mapper:\n  " + section + ":\n";
  const std::string prefix = section.empty() ? "mapper." : "mapper." + section + ".";
  const int key_line = FirstExtraLine() + (section.empty() ? 1 : 2);

  const ConfigError unknown = SettingsError(head + indent + "no_such_key_at_all: 1\n");
  EXPECT_EQ(unknown.file(), "platform.yaml");
  EXPECT_EQ(unknown.line(), key_line);
  EXPECT_EQ(unknown.key(), prefix + "no_such_key_at_all");
  EXPECT_NE(unknown.reason().find("unknown key"), std::string::npos) << unknown.reason();

  const std::string setting = c.out_of_range;
  const ConfigError range = SettingsError(head + indent + "min_points_to_match: 40\n" + indent + setting + "\n");
  if (section.empty()) {  // the top level has min_points_to_match itself
    EXPECT_EQ(range.line(), key_line + 1) << range.what();
  } else {
    // min_points_to_match is not in the section: the first error is that one.
    EXPECT_EQ(range.line(), key_line) << range.what();
    const ConfigError alone = SettingsError(head + indent + setting + "\n");
    EXPECT_EQ(alone.file(), "platform.yaml");
    EXPECT_EQ(alone.line(), key_line) << alone.what();
    EXPECT_EQ(alone.key(), prefix + setting.substr(0, setting.find(':'))) << alone.what();
    return;
  }
  EXPECT_EQ(range.key(), prefix + setting.substr(0, setting.find(':'))) << range.what();
}

INSTANTIATE_TEST_SUITE_P(
    EverySection, MapperSettingsSectionTest,
    ::testing::Values(SectionCase{"eskf", "gravity_m_s2: -1"}, SectionCase{"motion", "velocity_sigma_m_s: -1"},
                      SectionCase{"gpf", "num_particles: 5"}, SectionCase{"map", "prob_hit: 0.3"},
                      SectionCase{"reacquire", "coarse_factor: 0"}, SectionCase{"line_gap_fill", "step_m: 0"},
                      SectionCase{"graph", "max_iterations: 0"}, SectionCase{"loop_closure", "min_score: 1.5"},
                      SectionCase{"loop_search", "every_3d_scans: 0"}, SectionCase{"", "scan_sigma_position_m: 0"}));

TEST(MapperSettingsTest, TypeGroupAndElsewhereErrors) {
  const int line = FirstExtraLine() + 2;
  ConfigError e = SettingsError("mapper:\n  gpf:\n    num_particles: 2.5\n");
  EXPECT_EQ(e.line(), line);
  EXPECT_NE(e.reason().find("expected a whole number"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  gpf:\n    planar: 1\n");
  EXPECT_NE(e.reason().find("expected true or false"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  gpf:\n    num_particle: 200\n");
  EXPECT_NE(e.reason().find("did you mean mapper.gpf.num_particles?"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  num_particles: 200\n");
  EXPECT_NE(e.reason().find("did you mean mapper.gpf.num_particles?"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  gpf: 3\n");
  EXPECT_EQ(e.key(), "mapper.gpf");
  EXPECT_NE(e.reason().find("its keys: num_particles"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  map:\n    resolution_m: 0.2\n");
  EXPECT_NE(e.reason().find("distance_map_resolution_m"), std::string::npos) << e.what();
  e = SettingsError("mapper:\n  gpf:\n    seed: 3\n");
  EXPECT_NE(e.reason().find("--seed"), std::string::npos) << e.what();
}

// The submaps of unimap run keep their surfaces in SurfaceDistanceLayer,
// which does not read these keys: setting one for a run is an error naming
// the file, line and key, while unimap localize's prior map takes it.
TEST(MapperSettingsTest, MapKeysTheSubmapsDoNotReadAreErrorsForARun) {
  const int line = FirstExtraLine() + 2;
  for (const char* setting :
       {"subvoxel_surfaces: true", "signed_surfaces: true", "cell_planes: true", "recenter_fraction: 0.3",
        "growth_margin_m: 0.4", "max_edt_cells: 1000000", "max_occupied_voxels: 100000", "occupancy_threshold: 0.6",
        "clear_occupied_only: true", "discretize_rays: true"}) {
    const std::string text = setting;
    const ConfigError e = SettingsError("mapper:\n  map:\n    " + text + "\n");
    EXPECT_EQ(e.file(), "platform.yaml") << text;
    EXPECT_EQ(e.line(), line) << text;
    EXPECT_EQ(e.key(), "mapper.map." + text.substr(0, text.find(':'))) << text;
    EXPECT_NE(e.reason().find("not read by unimap run's submaps"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("unimap localize"), std::string::npos) << e.what();
  }
  // A key they read is taken, and the prior map takes the others.
  EXPECT_EQ(MapperOptionsFor(WithSettings("mapper:\n  map:\n    prob_miss: 0.45\n")).submaps.map.prob_miss, 0.45);
  const Platform prior = WithSettings("mapper:\n  map:\n    signed_surfaces: false\n    max_edt_cells: 1000000\n");
  EXPECT_FALSE(PriorMapOptionsFor(prior).map.signed_surfaces);
  EXPECT_EQ(PriorMapOptionsFor(prior).map.max_edt_cells, 1000000u);
}

TEST(MapperSettingsTest, PriorMapOptionsTakeTheLocalizerKeys) {
  const Platform platform = WithSettings("mapper:\n  gpf:\n    num_particles: 333\n  graph:\n    max_iterations: 3\n");
  EXPECT_EQ(PriorMapOptionsFor(platform).gpf.num_particles, 333);
  EXPECT_TRUE(PriorMapOptionsFor(platform).localize_only);
}

TEST(MapperSettingsTest, ListingSaysWhereEachValueCameFrom) {
  const std::vector<MapperSettingRow> rows =
      ListMapperSettings(WithSettings("mapper:\n  gpf:\n    clamp_distance_m: 0.8\n"));
  auto find = [&](const std::string& key) {
    for (const MapperSettingRow& row : rows) {
      if (row.key == key) return row;
    }
    ADD_FAILURE() << key << " not listed";
    return MapperSettingRow{};
  };
  EXPECT_EQ(find("mapper.gpf.clamp_distance_m").source, "platform.yaml:" + std::to_string(FirstExtraLine() + 2));
  EXPECT_EQ(find("mapper.gpf.clamp_distance_m").value, "0.8");
  EXPECT_EQ(find("mapper.gpf.clamp_distance_m").unit, "m");
  EXPECT_EQ(find("mapper.map.clamp_distance_m").source, "derived");
  EXPECT_EQ(find("mapper.gpf.num_particles").source, "platform");  // FromPlatform: 100
  EXPECT_EQ(find("mapper.graph.max_iterations").source, "default");
  // Every section is listed, and every key once.
  std::set<std::string> keys;
  for (const MapperSettingRow& row : rows) EXPECT_TRUE(keys.insert(row.key).second) << row.key;
  for (const char* section :
       {"eskf", "motion", "gpf", "map", "reacquire", "line_gap_fill", "graph", "loop_closure", "loop_search"}) {
    const std::string prefix = std::string("mapper.") + section + ".";
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const MapperSettingRow& r) {
      return r.key.rfind(prefix, 0) == 0;
    })) << prefix;
  }
}

// The scene's scale coarsens the voxel and everything FromPlatform derives
// from it, exactly as a platform file with that voxel would.
TEST(MapperSettingsTest, SceneScaleCoarsensTheVoxelAsThePlatformFileWould) {
  const Platform platform = WithSettings("");
  const MapperOptions near = MapperOptionsFor(platform, SceneScale{1.5, 1000, 40});
  EXPECT_EQ(Rows(near), Rows(MapperOptionsFor(platform)));
  SceneScale far{9.18, 1000, 40};  // 91.8 of the platform's 0.1 m voxels: 3 x
  const MapperOptions coarse = MapperOptionsFor(platform, far);
  EXPECT_DOUBLE_EQ(coarse.submaps.map.resolution_m, 0.3);
  std::ifstream in(test::kPlatform);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string key = "distance_map_resolution_m: 0.1";
  ASSERT_NE(yaml.find(key), std::string::npos);
  yaml.replace(yaml.find(key), key.size(), "distance_map_resolution_m: 0.3");
  EXPECT_EQ(Rows(coarse), Rows(MapperOptionsFor(LoadPlatformFromString(yaml, "platform.yaml"))));
}

// A `mapper:` value that holds at the platform's voxel but not at the
// scene's coarser one is an error naming the key, the voxel and the scene.
TEST(MapperSettingsTest, ASettingInvalidOnlyAtTheScenesVoxelNamesIt) {
  const Platform platform = WithSettings("mapper:\n  map:\n    clamp_distance_m: 0.2\n");
  EXPECT_NO_THROW(MapperOptionsFor(platform));                             // 0.2 m >= the 0.1 m voxel
  EXPECT_NO_THROW(MapperOptionsFor(platform, SceneScale{3.0, 1000, 40}));  // 30 voxels: 0.1 m kept
  try {
    MapperOptionsFor(platform, SceneScale{9.18, 1000, 40});  // 0.3 m: the clamp is below one voxel
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "mapper.map.clamp_distance_m") << e.what();
    EXPECT_EQ(e.line(), FirstExtraLine() + 2) << e.what();
    EXPECT_NE(e.reason().find("0.3 m that the scene's scale chose"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("median range of 9.18 m spans more than 40 of the platform's 0.1 m voxels"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace unimap::pipeline
