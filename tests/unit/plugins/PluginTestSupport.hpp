#pragma once
// Helpers shared by the payload plugin tests (tests/unit/plugins): load the
// in-tree plugins from the build tree, configure them with a few overrides,
// and build synthetic motion and encoder data with known truth.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "unimap/Deskew.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterValue.hpp"
#include "unimap/PluginLoader.hpp"

namespace unimap::plugin_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// The in-tree payload names.
inline const std::vector<std::string>& PayloadNames() {
  static const std::vector<std::string> names = {"fixed_3d", "rotating_3d", "rotating_2d"};
  return names;
}

// Test name suffix for a test parameterised over payload names.
inline std::string PayloadTestName(const ::testing::TestParamInfo<std::string>& param) { return param.param; }

// Loads an in-tree plugin from the build tree's plugin folder only.
inline LoadedPlugin LoadPayload(const std::string& name) {
  return PluginLoader({std::filesystem::path(UNIMAP_PLUGIN_BUILD_DIR)}).Load(name);
}

// The plugin's defaults with some keys replaced.
inline ParameterMap DefaultsWith(const PayloadPlugin& plugin, const std::map<std::string, ParameterValue>& overrides) {
  ParameterMap map = plugin.Defaults().DefaultMap();
  for (const auto& [key, value] : overrides) map.Set(key, value);
  return map;
}

// Configures the plugin with its defaults and some keys replaced.
inline void ConfigureWith(PayloadPlugin* plugin, const std::map<std::string, ParameterValue>& overrides) {
  plugin->Configure(DefaultsWith(*plugin, overrides));
}

// A body that does not move: T_world_body(t) = I.
inline MotionQuery StaticBody() {
  return [](double /*time_s*/) { return Eigen::Isometry3d::Identity(); };
}

// Rz(yaw) * Ry(pitch) * Rx(roll) with a translation, angles in degrees.
inline Eigen::Isometry3d PoseRpyDeg(const Eigen::Vector3d& translation_m, double roll_deg, double pitch_deg,
                                    double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = translation_m;
  return T;
}

// Wraps an angle into [0, 2pi) as a raw encoder reports it.
inline double WrapTwoPi(double angle_rad) {
  double wrapped = std::fmod(angle_rad, 2.0 * kPi);
  if (wrapped < 0.0) wrapped += 2.0 * kPi;
  return wrapped;
}

// Encoder of a motor turning at a constant rate: true (unwrapped) angle
// angle0_rad + rate_rad_s * (t - t0_s), sampled at sample_hz over [t0_s, t1_s]
// and reported wrapped into [0, 2pi).
inline EncoderTrack ConstantRateEncoder(double t0_s, double t1_s, double angle0_rad, double rate_rad_s,
                                        double sample_hz) {
  std::vector<EncoderSample> samples;
  const int count = static_cast<int>(std::ceil((t1_s - t0_s) * sample_hz)) + 1;
  for (int k = 0; k < count; ++k) {
    const double t = t0_s + static_cast<double>(k) / sample_hz;
    samples.push_back({t, WrapTwoPi(angle0_rad + rate_rad_s * (t - t0_s))});
  }
  return EncoderTrack(samples);
}

// A motor mount written out independently of the SDK: the analytic truth
//   T_body_lidar(theta) = T_body_motor * Rot(axis, theta) * T_motor_lidar,
//   theta = direction * encoder + offset.
struct MountTruth {
  Eigen::Vector3d body_motor_m{0.05, 0.0, -0.15};  // T_body_motor translation
  Eigen::Vector3d body_motor_rpy_deg{0.0, 0.0, 10.0};
  Eigen::Vector3d motor_lidar_m{0.0, 0.02, -0.1};  // T_motor_lidar translation
  Eigen::Vector3d motor_lidar_rpy_deg{90.0, 0.0, 0.0};
  Eigen::Vector3d axis{0.0, 0.0, 1.0};  // unit
  double offset_deg = 25.0;
  int direction = -1;

  // The platform keys that configure a plugin with this mount.
  std::map<std::string, ParameterValue> Overrides() const {
    const auto list = [](const Eigen::Vector3d& v) { return std::vector<double>{v.x(), v.y(), v.z()}; };
    return {{"extrinsic.body_motor.translation_m", list(body_motor_m)},
            {"extrinsic.body_motor.rpy_deg", list(body_motor_rpy_deg)},
            {"extrinsic.motor_lidar.translation_m", list(motor_lidar_m)},
            {"extrinsic.motor_lidar.rpy_deg", list(motor_lidar_rpy_deg)},
            {"motor.axis", list(axis)},
            {"motor.encoder_offset_deg", offset_deg},
            {"motor.encoder_direction", std::int64_t{direction}}};
  }
  // Motor angle (rad) for an unwrapped encoder angle (rad).
  double MotorAngle(double encoder_rad) const {
    return static_cast<double>(direction) * encoder_rad + offset_deg * kDeg;
  }
  // T_body_lidar at a motor angle (rad).
  Eigen::Isometry3d BodyFromLidar(double theta_rad) const {
    const Eigen::Vector3d& b = body_motor_rpy_deg;
    const Eigen::Vector3d& m = motor_lidar_rpy_deg;
    Eigen::Isometry3d R_motor = Eigen::Isometry3d::Identity();
    R_motor.linear() = Eigen::AngleAxisd(theta_rad, axis).toRotationMatrix();
    return PoseRpyDeg(body_motor_m, b.x(), b.y(), b.z()) * R_motor * PoseRpyDeg(motor_lidar_m, m.x(), m.y(), m.z());
  }
};

}  // namespace unimap::plugin_test
