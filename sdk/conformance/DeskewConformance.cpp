// Conformance: deskew is exact on closed-form synthetic motion, and
// Configure is idempotent (the same parameters give bit-identical output).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "PayloadConformanceTest.hpp"
#include "SyntheticRig.hpp"

namespace unimap::conformance {
namespace {

constexpr double kDeskewTolerance_m = 1e-3;  // 1 mm at 5-10 m range

// A value of the spec's type different from its default and within its
// range (the first of a few candidates that ParameterSet::Coerce accepts).
std::optional<ParameterValue> Modified(const ParameterSet& set, const ParameterSpec& spec) {
  std::vector<ParameterValue> candidates;
  if (const auto* b = std::get_if<bool>(&spec.default_value)) {
    candidates.emplace_back(!*b);
  } else if (const auto* i = std::get_if<std::int64_t>(&spec.default_value)) {
    candidates = {ParameterValue{*i + 1}, ParameterValue{*i - 1}, ParameterValue{-*i}};
  } else if (const auto* d = std::get_if<double>(&spec.default_value)) {
    const double step = std::max(0.1 * std::fabs(*d), 0.01);
    candidates = {ParameterValue{*d + step}, ParameterValue{*d - step}};
  } else if (const auto* list = std::get_if<std::vector<double>>(&spec.default_value)) {
    for (std::size_t k = 0; k < list->size(); ++k) {
      for (double step : {0.05, -0.05}) {
        std::vector<double> values = *list;
        values[k] += step;
        candidates.emplace_back(values);
      }
    }
  } else if (const auto* word = std::get_if<std::string>(&spec.default_value)) {
    for (const std::string& choice : spec.choices) {
      if (choice != *word) candidates.emplace_back(choice);
    }
  }
  for (const ParameterValue& candidate : candidates) {
    ParameterValue coerced;
    std::string why;
    if (candidate != spec.default_value && set.Coerce(spec.key, candidate, &coerced, &why)) {
      return coerced;
    }
  }
  return std::nullopt;
}

}  // namespace

// Points fired at random times in the scan window, seen from a body moving
// with constant linear (1 m/s) and angular (0.5 rad/s) velocity; Deskew must
// return each at T_world_body(t_end)^-1 * p_world, none dropped.
TEST_P(PayloadConformanceTest, DeskewExactOnSyntheticMotion) {
  const EncoderTrack encoder = SyntheticRig::EncoderFor(plugin());
  const RawScan scan = SyntheticRig::Scan(500, 21);
  const std::vector<Eigen::Vector3d> expected = SyntheticRig::ExpectedBodyPoints(plugin(), scan, encoder);

  // Self-check: the synthetic motion must matter (> 10 cm) for the test to mean anything.
  double largest_motion = 0.0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3d static_body =
        plugin().BodyFromLidarAt(encoder, scan.points[i].time_s) * scan.points[i].position_m;
    largest_motion = std::max(largest_motion, (expected[i] - static_body).norm());
  }
  ASSERT_GT(largest_motion, 0.1) << "conformance suite: synthetic motion too small";

  BodyScan out;
  try {
    out = plugin().Deskew(scan, encoder, &SyntheticRig::WorldFromBody);
  } catch (const std::exception& e) {
    FAIL() << Label() << ": Deskew of a valid synthetic scan threw: " << e.what();
  }
  EXPECT_EQ(out.reference_time_s, scan.end_time_s) << Label() << ": reference time is not the scan end";
  EXPECT_EQ(out.dropped_out_of_range, 0u) << Label() << ": dropped returns at 5-10 m range as out of range";
  ASSERT_EQ(out.points.size(), scan.points.size()) << Label() << ": Deskew dropped or added points";

  double worst = 0.0;
  std::size_t worst_index = 0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    EXPECT_EQ(out.points[i].time_s, scan.points[i].time_s)
        << Label() << ": point " << i << " lost its firing time (or the order changed)";
    const double error = (out.points[i].position_m - expected[i]).norm();
    if (!(error <= worst)) {
      worst = error;
      worst_index = i;
    }
  }
  EXPECT_LT(worst, kDeskewTolerance_m) << Label() << ": point " << worst_index
                                       << " (fired at t = " << scan.points[worst_index].time_s << " s) deskewed to ("
                                       << out.points[worst_index].position_m.transpose() << "), expected ("
                                       << expected[worst_index].transpose() << "): off by " << worst << " m";
}

// Configure(defaults) twice gives the output of once, bit for bit; so does
// Configure(modified) followed by Configure(defaults).
TEST_P(PayloadConformanceTest, ConfigureIsIdempotent) {
  const EncoderTrack encoder = SyntheticRig::EncoderFor(plugin());
  const RawScan scan = SyntheticRig::Scan(200, 41);
  const MotionQuery motion = &SyntheticRig::WorldFromBody;
  const ParameterSet set = plugin().Defaults();
  const ParameterMap defaults = set.DefaultMap();
  std::string why;

  // SetUp configured the fresh plugin with its defaults once.
  const BodyScan once = plugin().Deskew(scan, encoder, motion);
  plugin().Configure(defaults);
  const BodyScan twice = plugin().Deskew(scan, encoder, motion);
  EXPECT_TRUE(Identical(once, twice, &why))
      << Label() << ": Configure(defaults) twice changed the Deskew output: " << why;

  // Find a one-key change that Configure accepts, preferably one that
  // changes the output (an extrinsic, usually).
  std::string changed_key;
  bool output_changed = false;
  for (const ParameterSpec& spec : set.specs()) {
    const std::optional<ParameterValue> value = Modified(set, spec);
    if (!value) continue;
    ParameterMap modified = defaults;
    modified.Set(spec.key, *value);
    try {
      plugin().Configure(modified);
    } catch (const std::exception&) {
      continue;  // a cross-key constraint; try the next key
    }
    changed_key = spec.key;
    try {
      output_changed = !Identical(plugin().Deskew(scan, encoder, motion), once, &why);
    } catch (const std::exception&) {
      output_changed = true;
    }
    if (output_changed) break;
  }
  ASSERT_FALSE(changed_key.empty()) << Label() << ": Configure rejected every one-key change";
  RecordProperty("modified_key", changed_key);

  plugin().Configure(defaults);
  const BodyScan restored = plugin().Deskew(scan, encoder, motion);
  EXPECT_TRUE(Identical(once, restored, &why))
      << Label() << ": Configure(map with '" << changed_key
      << "' changed) then Configure(defaults) did not restore the output: " << why;
}

}  // namespace unimap::conformance
