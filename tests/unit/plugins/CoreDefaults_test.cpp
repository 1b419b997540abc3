// Each payload's defaults for the paper's seven per-platform parameters, and
// the reason each description gives for its value.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "PluginTestSupport.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {
namespace {

// N, M, I, sigma_a, sigma_g, distance-map resolution and max range per payload.
const std::map<std::string, CoreParameters>& ExpectedCoreDefaults() {
  static const std::map<std::string, CoreParameters> expected = {
      {"fixed_3d", {5, 20, 10, 0.02, 0.002, 0.1, 20.0}},
      {"rotating_3d", {10, 20, 10, 0.02, 0.002, 0.3, 20.0}},
      {"rotating_2d", {40, 20, 10, 0.02, 0.002, 0.1, 30.0}},
  };
  return expected;
}

class CoreDefaultsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CoreDefaultsTest, PaperParametersHaveThePlatformsValuesAndReasons) {
  const LoadedPlugin loaded = plugin_test::LoadPayload(GetParam());
  EXPECT_EQ(loaded.plugin->Name(), GetParam());
  EXPECT_FALSE(loaded.plugin->Description().empty());
  const ParameterSet defaults = loaded.plugin->Defaults();
  const CoreParameters actual = CoreParameters::FromMap(defaults.DefaultMap());
  const CoreParameters& expected = ExpectedCoreDefaults().at(GetParam());
  EXPECT_EQ(actual.scans_per_3d_scan, expected.scans_per_3d_scan);
  EXPECT_EQ(actual.scans_3d_per_submap, expected.scans_3d_per_submap);
  EXPECT_EQ(actual.scans_3d_per_optimization, expected.scans_3d_per_optimization);
  EXPECT_EQ(actual.sigma_accel_m_s2, expected.sigma_accel_m_s2);
  EXPECT_EQ(actual.sigma_gyro_rad_s, expected.sigma_gyro_rad_s);
  EXPECT_EQ(actual.distance_map_resolution_m, expected.distance_map_resolution_m);
  EXPECT_EQ(actual.distance_map_max_range_m, expected.distance_map_max_range_m);

  // The description is the SDK's, extended with "; <why this value>".
  ParameterSet sdk;
  expected.AddTo(&sdk);
  for (const std::string& key : CoreParameters::Keys()) {
    const ParameterSpec* spec = defaults.Find(key);
    ASSERT_NE(spec, nullptr) << key;
    const std::string& base = sdk.Find(key)->description;
    EXPECT_EQ(spec->description.rfind(base + "; ", 0), 0u) << key << ": " << spec->description;
    EXPECT_GT(spec->description.size(), base.size() + 10) << key;
  }
}

INSTANTIATE_TEST_SUITE_P(AllPayloads, CoreDefaultsTest, ::testing::ValuesIn(plugin_test::PayloadNames()),
                         plugin_test::PayloadTestName);

}  // namespace
}  // namespace unimap
