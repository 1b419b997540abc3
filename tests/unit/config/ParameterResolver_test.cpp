#include "config/ParameterResolver.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Passes when text contains part; the failure message shows both.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// A small set with one parameter of every type.
ParameterSet TestSet() {
  ParameterSet set;
  set.Add({"count", "N", "a count (count)", std::int64_t{5}, 1, 100, {}});
  set.Add({"gain", "", "a gain (1)", 0.5, 0.0, 1.0, {}});
  set.Add({"mount.offset_m", "", "an offset (m)", std::vector<double>{0, 0, 0}, -1, 1, {}});
  set.Add({"mount.side", "", "a side (word)", std::string("left"), -kInf, kInf, {"left", "right"}});
  set.Add({"enabled", "", "a flag", true, -kInf, kInf, {}});
  return set;
}

// The ConfigError resolving text against TestSet() throws (a failure if none).
ConfigError ResolveError(const std::string& parameters_yaml) {
  const ParameterSet set = TestSet();
  try {
    ParameterResolver(set).Resolve(PlatformFile::Parse("plugin: x\nparameters:\n" + parameters_yaml, "p.yaml"));
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << parameters_yaml;
  return ConfigError("", 0, "", "");
}

TEST(EditDistanceTest, KnownDistances) {
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(EditDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(EditDistance("", "abc"), 3u);
  EXPECT_EQ(EditDistance("abc", ""), 3u);
  EXPECT_EQ(EditDistance("same", "same"), 0u);
  EXPECT_EQ(EditDistance("ab", "ba"), 2u);  // no transpositions
}

TEST(ParameterResolverTest, ClosestKeyWithinThreeEdits) {
  const ParameterSet set = TestSet();
  const ParameterResolver resolver(set);
  EXPECT_EQ(resolver.ClosestKey("cont"), "count");
  EXPECT_EQ(resolver.ClosestKey("mount.ofset_m"), "mount.offset_m");
  EXPECT_EQ(resolver.ClosestKey("gainxyz"), "gain");  // 3 deletions: still suggested
  EXPECT_EQ(resolver.ClosestKey("gainwxyz"), "");     // 4 away from "gain", farther from the rest
  EXPECT_EQ(resolver.ClosestKey("gainwxyz", 4), "gain");
}

TEST(ParameterResolverTest, DefaultsOverriddenWithProvenance) {
  const ParameterSet set = TestSet();
  const PlatformFile file = PlatformFile::Parse(
      "plugin: x\n"                     // 1
      "parameters:\n"                   // 2
      "  gain: 1\n"                     // 3: an integer where a number is expected
      "  mount:\n"                      // 4
      "    offset_m: [0.25, -1, 0]\n",  // 5
      "p.yaml");
  const ResolvedParameters resolved = ParameterResolver(set).Resolve(file);

  ParameterMap expected = set.DefaultMap();
  expected.Set("gain", 1.0);
  expected.Set("mount.offset_m", std::vector<double>{0.25, -1.0, 0.0});
  EXPECT_EQ(resolved.parameters, expected);
  EXPECT_TRUE(std::holds_alternative<double>(resolved.parameters.At("gain")));

  ASSERT_EQ(resolved.effective.size(), set.specs().size());
  const std::vector<int> lines = {0, 3, 5, 0, 0};
  for (std::size_t i = 0; i < set.specs().size(); ++i) {
    const EffectiveParameter& effective = resolved.effective[i];
    EXPECT_EQ(effective.spec.key, set.specs()[i].key);
    EXPECT_EQ(effective.value, expected.At(effective.spec.key));
    EXPECT_EQ(effective.line, lines[i]) << effective.spec.key;
    EXPECT_EQ(effective.source, lines[i] == 0 ? ParameterSource::kPluginDefault : ParameterSource::kPlatformFile)
        << effective.spec.key;
  }
}

TEST(ParameterResolverTest, UnknownKeySuggestsTheClosest) {
  const ConfigError e = ResolveError("  count: 3\n  gian: 0.1\n");
  EXPECT_EQ(e.file(), "p.yaml");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.key(), "gian");
  EXPECT_EQ(e.reason(), "unknown parameter (did you mean 'gain'?)");
  EXPECT_EQ(ResolveError("  totally_different: 1\n").reason(), "unknown parameter");
}

TEST(ParameterResolverTest, GroupNameAndNestedValueAreExplained) {
  const ConfigError group = ResolveError("  mount: 3\n");
  EXPECT_EQ(group.key(), "mount");
  EXPECT_TRUE(Contains(group.reason(), "is a group"));
  EXPECT_TRUE(Contains(group.reason(), "its parameters are mount.offset_m, mount.side"));

  const ConfigError nested = ResolveError("  gain:\n    low: 1\n");
  EXPECT_EQ(nested.key(), "gain.low");
  EXPECT_EQ(nested.line(), 4);
  EXPECT_TRUE(Contains(nested.reason(), "'gain' takes a value"));
}

TEST(ParameterResolverTest, TypeRangeLengthAndChoiceErrors) {
  struct Case {
    std::string yaml;   // lines under `parameters:` (line 3 on)
    std::string key;    // expected key
    std::string words;  // expected in the reason
  };
  const std::vector<Case> cases = {
      {"  count: 1.5\n", "count", "expected integer, got number 1.5"},
      {"  count: many\n", "count", "expected integer, got string many"},
      {"  enabled: yes\n", "enabled", "expected bool, got string yes"},
      {"  gain: [1]\n", "gain", "expected number, got list of numbers"},
      {"  mount:\n    offset_m: 2\n", "mount.offset_m", "expected list of numbers, got integer 2"},
      {"  count: 0\n", "count", "out of range [1, 100]"},
      {"  gain: 1.5\n", "gain", "out of range [0, 1]"},
      {"  mount.offset_m: [0, 0, -2]\n", "mount.offset_m", "out of range [-1, 1]"},
      {"  mount.offset_m: [0, 0]\n", "mount.offset_m", "expected a list of 3 numbers, got 2"},
      {"  mount.side: up\n", "mount.side", "'up' is not one of: left, right"},
  };
  for (const Case& c : cases) {
    const ConfigError e = ResolveError(c.yaml);
    EXPECT_EQ(e.file(), "p.yaml") << c.yaml;
    EXPECT_EQ(e.line(), c.yaml.find('\n') + 1 == c.yaml.size() ? 3 : 4) << c.yaml;
    EXPECT_EQ(e.key(), c.key) << c.yaml;
    EXPECT_TRUE(Contains(e.reason(), c.words)) << c.yaml;
  }
}

}  // namespace
}  // namespace unimap
