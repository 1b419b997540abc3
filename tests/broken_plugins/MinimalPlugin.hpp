#pragma once
// A trivial but complete payload plugin for the loader and platform-file
// tests: no sensor model to speak of, a small parameter set covering every
// value type, and a Configure() that remembers what it was given.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap_test {

class MinimalPlugin : public unimap::PayloadPlugin {
 public:
  // "test_valid", the name of the library this class is exported from.
  std::string Name() const override { return "test_valid"; }

  // Reports the configured values the tests look at, so they can see what
  // reached the plugin through the public interface alone.
  std::string Description() const override {
    return "minimal test payload; configured " + std::to_string(configure_count_) +
           " times; N=" + std::to_string(scans_per_3d_scan_) + "; direction=" + direction_;
  }

  // The seven core keys (CoreParameters defaults) plus one key of each other type.
  unimap::ParameterSet Defaults() const override {
    unimap::ParameterSet set;
    unimap::CoreParameters().AddTo(&set);
    set.Add({"extrinsic.body_motor.translation_m",
             "",
             "motor origin in the body frame (m)",
             std::vector<double>{0.0, 0.0, 0.1},
             -10.0,
             10.0,
             {}});
    set.Add({"extrinsic.body_motor.rpy_deg",
             "",
             "motor orientation in the body frame (deg)",
             std::vector<double>{0.0, 0.0, 0.0},
             -360.0,
             360.0,
             {}});
    set.Add({"motor.direction",
             "",
             "motor spin direction (word)",
             std::string("ccw"),
             -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(),
             {"cw", "ccw"}});
    set.Add({"motor.enabled",
             "",
             "whether the motor turns (flag)",
             true,
             -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(),
             {}});
    set.Add({"label",
             "",
             "free text naming the rig (word)",
             std::string("bench"),
             -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(),
             {}});
    return set;
  }

  // Checks one cross-key rule itself (with an empty file name and line, as a
  // plugin does), then the core rules through CoreParameters::FromMap.
  void Configure(const unimap::ParameterMap& parameters) override {
    if (parameters.GetDouble("distance_map_resolution_m") * 4.0 > parameters.GetDouble("distance_map_max_range_m")) {
      throw unimap::ConfigError("", 0, "distance_map_resolution_m",
                                "must be at most a quarter of distance_map_max_range_m");
    }
    const unimap::CoreParameters core = unimap::CoreParameters::FromMap(parameters);
    scans_per_3d_scan_ = core.scans_per_3d_scan;
    direction_ = parameters.GetString("motor.direction");
    ++configure_count_;
  }

  bool UsesEncoder() const override { return false; }

  double MotorAngleAt(const unimap::EncoderTrack& /*encoder*/, double /*time_s*/) const override { return 0.0; }

  Eigen::Isometry3d BodyFromLidarAt(const unimap::EncoderTrack& /*encoder*/, double /*time_s*/) const override {
    return Eigen::Isometry3d::Identity();
  }

  unimap::BodyScan Deskew(const unimap::RawScan& scan, const unimap::EncoderTrack& /*encoder*/,
                          const unimap::MotionQuery& T_world_body_at) const override {
    return unimap::DeskewScan(scan, [](double) { return Eigen::Isometry3d::Identity(); }, T_world_body_at, {});
  }

 private:
  int configure_count_ = 0;    // successful Configure() calls
  int scans_per_3d_scan_ = 0;  // N after the last Configure()
  std::string direction_;      // motor.direction after the last Configure()
};

}  // namespace unimap_test
