// Conformance: bad input is rejected with InputError, never a crash or a
// silently wrong scan.
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PayloadConformanceTest.hpp"
#include "SyntheticRig.hpp"
#include "unimap/Errors.hpp"

namespace unimap::conformance {

TEST_P(PayloadConformanceTest, BadScansRejected) {
  const EncoderTrack encoder = SyntheticRig::EncoderFor(plugin());
  const MotionQuery motion = &SyntheticRig::WorldFromBody;
  const RawScan valid = SyntheticRig::Scan(50, 31);
  try {
    plugin().Deskew(valid, encoder, motion);
  } catch (const std::exception& e) {
    FAIL() << Label() << ": Deskew of a valid synthetic scan threw: " << e.what();
  }
  const auto expect_input_error = [&](const RawScan& scan, const EncoderTrack& track, const std::string& what) {
    try {
      plugin().Deskew(scan, track, motion);
      ADD_FAILURE() << Label() << ": Deskew accepted " << what;
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << Label() << ": Deskew threw a non-InputError for " << what << ": " << e.what();
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  RawScan scan = valid;
  scan.points[17].position_m.x() = nan;
  expect_input_error(scan, encoder, "a NaN coordinate");
  scan = valid;
  scan.points[3].position_m.y() = inf;
  expect_input_error(scan, encoder, "an infinite coordinate");
  scan = valid;
  scan.points[40].position_m.z() = -inf;
  expect_input_error(scan, encoder, "a -inf coordinate");
  scan = valid;
  scan.points[8].time_s = nan;
  expect_input_error(scan, encoder, "a NaN point time");
  scan = valid;
  scan.end_time_s = scan.start_time_s - 0.01;
  expect_input_error(scan, encoder, "end_time_s < start_time_s");
  scan = valid;
  scan.points[10].time_s = scan.end_time_s + 0.01;
  expect_input_error(scan, encoder, "a point time after end_time_s");
  scan = valid;
  scan.points[0].time_s = scan.start_time_s - 0.01;
  expect_input_error(scan, encoder, "a point time before start_time_s");
  scan = valid;
  scan.points.clear();
  expect_input_error(scan, encoder, "an empty scan");

  if (plugin().UsesEncoder()) {
    // The same scan 1.5 s later: past the encoder's last sample (2.0 s).
    scan = valid;
    scan.start_time_s += 1.5;
    scan.end_time_s += 1.5;
    for (Point& p : scan.points) p.time_s += 1.5;
    expect_input_error(scan, encoder, "point times outside encoder coverage");
    expect_input_error(valid, EncoderTrack(), "a scan without encoder samples");
  }
}

TEST_P(PayloadConformanceTest, EncoderTimeGoingBackwardsRejected) {
  if (!plugin().UsesEncoder()) GTEST_SKIP() << "payload has no motor";
  const std::vector<EncoderSample> backwards = {{0.00, 0.0}, {0.01, 0.033}, {0.005, 0.066}};
  EXPECT_THROW(EncoderTrack{backwards}, InputError) << "encoder time going backwards must throw InputError";
  const std::vector<EncoderSample> repeated = {{0.00, 0.0}, {0.01, 0.033}, {0.01, 0.066}};
  EXPECT_THROW(EncoderTrack{repeated}, InputError) << "a repeated encoder time must throw InputError";
  EncoderTrack track(std::vector<EncoderSample>{{0.00, 0.0}, {0.01, 0.033}});
  EXPECT_THROW(track.Append({0.005, 0.066}), InputError) << "appending an earlier encoder sample must throw InputError";
}

}  // namespace unimap::conformance
