#include "unimap/ParameterSet.hpp"

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

ParameterSet Example() {
  ParameterSet set;
  set.Add({"count", "N", "a count", std::int64_t{4}, 1, 10, {}});
  set.Add({"rate_hz", "", "a rate (Hz)", 10.0, 0.0, 100.0, {}});
  set.Add({"enabled", "", "a flag", true, -1e300, 1e300, {}});
  set.Add({"mode", "", "a mode", std::string("fast"), -1e300, 1e300, {"fast", "slow"}});
  set.Add({"xyz_m", "", "a vector (m)", std::vector<double>{0, 0, 1}, -5, 5, {}});
  return set;
}

TEST(ParameterSet, DefaultsAreValidAndMapped) {
  const ParameterSet set = Example();
  std::string why;
  EXPECT_TRUE(set.IsValid(&why)) << why;
  const ParameterMap map = set.DefaultMap();
  EXPECT_EQ(map.GetInt("count"), 4);
  EXPECT_DOUBLE_EQ(map.GetDouble("rate_hz"), 10.0);
  EXPECT_TRUE(map.GetBool("enabled"));
  EXPECT_EQ(map.GetString("mode"), "fast");
  EXPECT_EQ(map.GetVector3("xyz_m"), Eigen::Vector3d(0, 0, 1));
  EXPECT_NO_THROW(set.Validate(map));
}

TEST(ParameterSet, CoerceConvertsIntegersToNumbersOnly) {
  const ParameterSet set = Example();
  ParameterValue out;
  std::string why;
  ASSERT_TRUE(set.Coerce("rate_hz", std::int64_t{20}, &out, &why)) << why;
  EXPECT_EQ(out, ParameterValue(20.0));
  EXPECT_FALSE(set.Coerce("count", 1.5, &out, &why));
  EXPECT_EQ(why, "expected integer, got number 1.5");
  EXPECT_FALSE(set.Coerce("enabled", std::int64_t{1}, &out, &why));
  EXPECT_EQ(why, "expected bool, got integer 1");
}

TEST(ParameterSet, CoerceChecksRangeSizeAndChoices) {
  const ParameterSet set = Example();
  ParameterValue out;
  std::string why;
  EXPECT_FALSE(set.Coerce("count", std::int64_t{11}, &out, &why));
  EXPECT_NE(why.find("out of range [1, 10]"), std::string::npos) << why;
  EXPECT_FALSE(set.Coerce("xyz_m", std::vector<double>{1, 2}, &out, &why));
  EXPECT_EQ(why, "expected a list of 3 numbers, got 2");
  EXPECT_FALSE(set.Coerce("xyz_m", std::vector<double>{1, 2, 6}, &out, &why));
  EXPECT_FALSE(set.Coerce("mode", std::string("medium"), &out, &why));
  EXPECT_EQ(why, "'medium' is not one of: fast, slow");
  EXPECT_FALSE(set.Coerce("nope", 1.0, &out, &why));
  EXPECT_EQ(why, "unknown parameter");
}

TEST(ParameterSet, ValidateNamesTheKey) {
  const ParameterSet set = Example();
  ParameterMap map = set.DefaultMap();
  map.Set("rate_hz", -1.0);
  try {
    set.Validate(map);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "rate_hz");
  }
  ParameterMap missing;
  EXPECT_THROW(set.Validate(missing), ConfigError);
}

TEST(ParameterSet, InvalidDefaultsAndDuplicatesAreCaught) {
  ParameterSet set;
  set.Add({"a", "", "bad default", 50.0, 0.0, 10.0, {}});
  std::string why;
  EXPECT_FALSE(set.IsValid(&why));
  EXPECT_NE(why.find("default of 'a'"), std::string::npos) << why;
  EXPECT_THROW(set.Add({"a", "", "again", 1.0, 0.0, 10.0, {}}), std::logic_error);
}

TEST(ParameterMap, TypedGettersNameKeyOnMismatch) {
  ParameterMap map;
  map.Set("n", std::int64_t{3});
  EXPECT_DOUBLE_EQ(map.GetDouble("n"), 3.0);
  try {
    map.GetString("n");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "n");
    EXPECT_EQ(e.reason(), "expected string, got integer 3");
  }
  EXPECT_THROW(map.At("missing"), ConfigError);
}

TEST(ParameterValue, ToStringRoundTripsNumbers) {
  EXPECT_EQ(ToString(ParameterValue(0.1)), "0.1");
  EXPECT_EQ(ToString(ParameterValue(std::vector<double>{0, -1.5, 1e-3})), "[0, -1.5, 0.001]");
  EXPECT_EQ(std::stod(ToString(ParameterValue(1.0 / 3.0))), 1.0 / 3.0);
  EXPECT_EQ(ToString(ParameterValue(false)), "false");
}

}  // namespace
}  // namespace unimap
