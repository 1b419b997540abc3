#include "ScenarioVariant.hpp"

#include <cmath>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

bool Positive(double value) { return std::isfinite(value) && value > 0.0; }

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

bool ScenarioVariant::IsValid(std::string* why) const {
  const char* bad = !Positive(speed_scale)       ? "--speed-scale"
                    : !Positive(imu_noise_scale) ? "--imu-noise-scale"
                    : !Positive(imu_bias_scale)  ? "--imu-bias-scale"
                                                 : nullptr;
  if (bad == nullptr) return true;
  if (why != nullptr) *why = std::string(bad) + " must be a finite number > 0";
  return false;
}

std::string ScenarioVariant::Describe() const {
  if (IsIdentity()) return "nominal";
  std::string out;
  const auto add = [&out](double scale, const char* what) {
    if (scale == 1.0) return;
    if (!out.empty()) out += ", ";
    out += "x" + Number(scale) + " " + what;
  };
  add(speed_scale, "speed");
  add(imu_noise_scale, "IMU noise");
  add(imu_bias_scale, "IMU bias");
  return out;
}

Scenario ApplyVariant(Scenario scenario, const ScenarioVariant& variant) {
  std::string why;
  if (!variant.IsValid(&why)) throw ConfigError(scenario.file, 0, "variant", why);
  const double s = variant.speed_scale;
  // Time compressed by S along the same path: velocities x S, accelerations x S^2.
  scenario.trajectory.max_speed_m_s *= s;
  scenario.trajectory.max_yaw_rate_rad_s *= s;
  scenario.trajectory.max_acceleration_m_s2 *= s * s;
  for (std::size_t i = 1; i < scenario.waypoints.size(); ++i) scenario.waypoints[i].dwell_s /= s;
  // The first waypoint's dwell follows the static start: part of the start, kept.
  ImuNoise& n = scenario.imu.noise;
  n.accel_noise_m_s2 *= variant.imu_noise_scale;
  n.gyro_noise_rad_s *= variant.imu_noise_scale;
  n.accel_bias_m_s2 *= variant.imu_bias_scale;
  n.gyro_bias_rad_s *= variant.imu_bias_scale;
  n.accel_bias_walk_m_s2_sqrt_s *= variant.imu_bias_scale;
  n.gyro_bias_walk_rad_s_sqrt_s *= variant.imu_bias_scale;
  // scenario.yaml in the dataset says which variant made it.
  if (!variant.IsIdentity()) scenario.text = "# variant: " + variant.Describe() + "\n" + scenario.text;
  return scenario;
}

}  // namespace unimap::sim
