// Conformance: the plugin loads, reports its ABI and has valid,
// self-consistent defaults that Configure accepts (and bad maps it rejects).
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "PayloadConformanceTest.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Version.hpp"

namespace unimap::conformance {
namespace {

// map without key.
ParameterMap Without(const ParameterMap& map, const std::string& key) {
  ParameterMap out;
  for (const auto& [k, v] : map.values()) {
    if (k != key) out.Set(k, v);
  }
  return out;
}

// A value of the spec's type just outside its range (below the minimum if it
// is finite, else above the maximum), for numbers and lists of numbers;
// false when the spec has no finite bound or is not numeric.
bool OutOfRangeValue(const ParameterSpec& spec, ParameterValue* out) {
  const bool has_min = spec.min_value > -std::numeric_limits<double>::infinity();
  const bool has_max = spec.max_value < std::numeric_limits<double>::infinity();
  if (!has_min && !has_max) return false;
  const double bad = has_min ? spec.min_value - 1.0 : spec.max_value + 1.0;
  if (std::holds_alternative<std::int64_t>(spec.default_value)) {
    if (!(std::fabs(bad) < 9.0e18)) return false;  // not representable
    *out = static_cast<std::int64_t>(has_min ? std::floor(bad) : std::ceil(bad));
    return true;
  }
  if (std::holds_alternative<double>(spec.default_value)) {
    *out = bad;
    return true;
  }
  if (const auto* list = std::get_if<std::vector<double>>(&spec.default_value)) {
    if (list->empty()) return false;
    std::vector<double> values = *list;
    values.front() = bad;
    *out = values;
    return true;
  }
  return false;
}

}  // namespace

TEST_P(PayloadConformanceTest, Loads) {
  const std::string name = plugin().Name();
  ASSERT_FALSE(name.empty()) << loaded().library_path << ": Name() is empty";
  EXPECT_EQ(loaded().library_path.filename().string(), "libunimap_payload_" + name + ".so")
      << "the library of payload '" << name
      << "' must be named libunimap_payload_<Name()>.so so the loader finds it by name";
  EXPECT_FALSE(plugin().Description().empty()) << Label() << ": Description() is empty";
}

TEST_P(PayloadConformanceTest, Version) {
  EXPECT_EQ(loaded().abi_version, kPayloadAbiVersion)
      << Label() << " was built against PayloadPlugin ABI " << loaded().abi_version << ", this SDK is ABI "
      << kPayloadAbiVersion;
}

TEST_P(PayloadConformanceTest, DefaultsValidAndSelfConsistent) {
  const ParameterSet defaults = plugin().Defaults();
  std::string why;
  EXPECT_TRUE(defaults.IsValid(&why)) << Label() << ": Defaults() is not valid: " << why;

  // Every paper parameter (Table 1) is declared with the SDK's type.
  ParameterSet core_reference;
  CoreParameters{}.AddTo(&core_reference);
  for (const std::string& key : CoreParameters::Keys()) {
    const ParameterSpec* spec = defaults.Find(key);
    const ParameterSpec* reference = core_reference.Find(key);
    ASSERT_NE(reference, nullptr) << "SDK: CoreParameters::AddTo lacks " << key;
    if (spec == nullptr) {
      ADD_FAILURE() << Label() << ": Defaults() lacks the core parameter '" << key << "'";
      continue;
    }
    EXPECT_EQ(spec->default_value.index(), reference->default_value.index())
        << Label() << ": core parameter '" << key << "' is a " << TypeName(spec->default_value)
        << ", the SDK declares it a " << TypeName(reference->default_value);
  }

  const ParameterMap map = defaults.DefaultMap();
  EXPECT_EQ(map, plugin().Defaults().DefaultMap()) << Label() << ": Defaults() is not deterministic";
  try {
    const CoreParameters core = CoreParameters::FromMap(map);
    EXPECT_TRUE(core.IsValid(&why)) << Label() << ": default core parameters invalid: " << why;
  } catch (const std::exception& e) {
    ADD_FAILURE() << Label() << ": CoreParameters::FromMap(defaults) threw: " << e.what();
  }
  try {
    plugin().Configure(map);
  } catch (const std::exception& e) {
    ADD_FAILURE() << Label() << ": Configure(Defaults().DefaultMap()) threw: " << e.what();
  }
}

// Configure rejects a map with a missing core key, an unknown key, a value
// out of range or of the wrong type, with a ConfigError naming the key.
TEST_P(PayloadConformanceTest, ConfigureRejectsBadMaps) {
  const ParameterSet defaults = plugin().Defaults();
  const ParameterMap map = defaults.DefaultMap();
  const auto expect_rejected = [&](const ParameterMap& bad, const std::string& key, const std::string& what) {
    try {
      plugin().Configure(bad);
      ADD_FAILURE() << Label() << ": Configure accepted a map with " << what;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos)
          << Label() << ": the ConfigError for " << what << " does not name the key '" << key << "': " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << Label() << ": Configure threw a non-ConfigError for " << what << ": " << e.what();
    }
  };

  for (const std::string& key : CoreParameters::Keys()) {
    expect_rejected(Without(map, key), key, "the core key '" + key + "' missing");
  }
  ParameterMap unknown = map;
  unknown.Set("conformance.no_such_key", 1.0);
  expect_rejected(unknown, "conformance.no_such_key", "an unknown key");

  for (const ParameterSpec& spec : defaults.specs()) {
    ParameterValue bad;
    if (OutOfRangeValue(spec, &bad)) {
      ParameterMap out_of_range = map;
      out_of_range.Set(spec.key, bad);
      expect_rejected(out_of_range, spec.key, "'" + spec.key + "' out of range (" + ToString(bad) + ")");
    }
    if (!std::holds_alternative<std::string>(spec.default_value)) {
      ParameterMap wrong_type = map;
      wrong_type.Set(spec.key, std::string("not-a-value"));
      expect_rejected(wrong_type, spec.key, "a word for '" + spec.key + "'");
    } else if (!spec.choices.empty()) {
      ParameterMap bad_choice = map;
      bad_choice.Set(spec.key, std::string("conformance-not-a-choice"));
      expect_rejected(bad_choice, spec.key, "an unknown choice for '" + spec.key + "'");
    }
  }
}

}  // namespace unimap::conformance
