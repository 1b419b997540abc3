#include "Scenario.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "ScenarioFields.hpp"
#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// A payload written as a path (contains '/' or ends in .yaml/.yml) resolves
// against the scenario's folder; a bare word is a plugin name.
std::string ResolvePayload(const std::string& payload, const std::filesystem::path& base_dir) {
  const std::filesystem::path path(payload);
  const std::string ext = path.extension().string();
  const bool is_path = payload.find('/') != std::string::npos || ext == ".yaml" || ext == ".yml";
  if (!is_path || path.is_absolute()) return payload;
  return (base_dir / path).lexically_normal().string();
}

void ReadImu(const ScenarioFields& f, ImuConfig* imu) {
  f.AllowOnly({"rate_hz", "gravity_m_s2", "accel_noise_m_s2", "gyro_noise_rad_s", "accel_bias_walk_m_s2_sqrt_s",
               "gyro_bias_walk_rad_s_sqrt_s", "accel_bias_m_s2", "gyro_bias_rad_s"});
  imu->rate_hz = f.Number("rate_hz", imu->rate_hz, 1.0, 10000.0);
  imu->gravity_m_s2 = f.Number("gravity_m_s2", imu->gravity_m_s2, 0.0, 100.0);
  ImuNoise& n = imu->noise;
  n.accel_noise_m_s2 = f.Number("accel_noise_m_s2", 0.0, 0.0, 10.0);
  n.gyro_noise_rad_s = f.Number("gyro_noise_rad_s", 0.0, 0.0, 1.0);
  n.accel_bias_walk_m_s2_sqrt_s = f.Number("accel_bias_walk_m_s2_sqrt_s", 0.0, 0.0, 1.0);
  n.gyro_bias_walk_rad_s_sqrt_s = f.Number("gyro_bias_walk_rad_s_sqrt_s", 0.0, 0.0, 1.0);
  n.accel_bias_m_s2 = f.Vector3("accel_bias_m_s2", Eigen::Vector3d::Zero());
  n.gyro_bias_rad_s = f.Vector3("gyro_bias_rad_s", Eigen::Vector3d::Zero());
}

void ReadEncoder(const ScenarioFields& f, Scenario* s) {
  f.AllowOnly({"rate_hz", "counts_per_revolution"});
  s->encoder_rate_hz = f.Number("rate_hz", s->encoder_rate_hz, 1.0, 100000.0);
  const std::int64_t counts = f.Integer("counts_per_revolution", 0, 0, std::int64_t{1} << 40);
  if (counts == 1)
    throw ConfigError(f.file(), f.LineOf("counts_per_revolution"), f.Name("counts_per_revolution"),
                      "must be 0 (not quantised) or at least 2");
  s->encoder_resolution_rad = counts == 0 ? 0.0 : 2.0 * M_PI / static_cast<double>(counts);
}

void ReadLidar(const ScenarioFields& f, Scenario* s) {
  f.AllowOnly({"range_noise_m", "dropout_probability", "azimuth_resolution_deg", "pose_knot_interval_s"});
  s->lidar_noise.range_sigma_m = f.Number("range_noise_m", 0.0, 0.0, 10.0);
  s->lidar_noise.dropout_probability = f.Number("dropout_probability", 0.0, 0.0, 0.99);
  s->azimuth_resolution_deg = f.Number("azimuth_resolution_deg", s->azimuth_resolution_deg, 0.01, 90.0);
  s->pose_knot_interval_s = f.Number("pose_knot_interval_s", s->pose_knot_interval_s, 0.0, 0.1);
}

void ReadWobble(const ScenarioFields& f, Wobble* w) {
  f.AllowOnly({"roll_deg", "pitch_deg", "roll_period_s", "pitch_period_s", "ramp_s"});
  w->roll_amplitude_rad = f.Number("roll_deg", 0.0, 0.0, 30.0) * kDegToRad;
  w->pitch_amplitude_rad = f.Number("pitch_deg", 0.0, 0.0, 30.0) * kDegToRad;
  w->roll_period_s = f.Number("roll_period_s", w->roll_period_s, 0.1, 1e6);
  w->pitch_period_s = f.Number("pitch_period_s", w->pitch_period_s, 0.1, 1e6);
  w->ramp_s = f.Number("ramp_s", w->ramp_s, 0.01, 1e6);
}

void ReadTrajectory(const ScenarioFields& f, Scenario* s) {
  f.AllowOnly(
      {"static_start_s", "max_speed_m_s", "max_acceleration_m_s2", "max_yaw_rate_deg_s", "wobble", "waypoints"});
  WaypointTrajectoryOptions& o = s->trajectory;
  o.static_start_s = f.Number("static_start_s", 3.0, 0.0, 1e6);
  o.max_speed_m_s = f.RequiredNumber("max_speed_m_s", 1e-3, 100.0);
  o.max_acceleration_m_s2 = f.Number("max_acceleration_m_s2", 0.5, 1e-3, 100.0);
  o.max_yaw_rate_rad_s = f.Number("max_yaw_rate_deg_s", 30.0, 1e-3, 3600.0) * kDegToRad;
  if (f.Has("wobble")) ReadWobble(f.Map("wobble"), &o.wobble);
  const YAML::Node list = f.Required("waypoints");
  if (!list.IsSequence() || list.size() == 0) {
    throw ConfigError(f.file(), YamlLine(list), f.Name("waypoints"), "must be a non-empty list of waypoints");
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ScenarioFields w(list[i], f.file(), f.Name("waypoints") + "[" + std::to_string(i) + "]");
    w.AllowOnly({"position", "yaw_deg", "dwell_s"});
    Waypoint point;
    point.position_m = w.RequiredVector3("position");
    point.yaw_rad = w.Number("yaw_deg", 0.0, -1e5, 1e5) * kDegToRad;
    point.dwell_s = w.Number("dwell_s", 0.0, 0.0, 1e6);
    s->waypoints.push_back(point);
  }
}

}  // namespace

WaypointTrajectory Scenario::MakeTrajectory() const {
  try {
    return WaypointTrajectory(waypoints, trajectory);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(file, 0, "trajectory", e.what());
  }
}

Scenario ParseScenario(const std::string& yaml_text, const std::string& file_label,
                       const std::filesystem::path& base_dir) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(file_label, e.mark.line >= 0 ? e.mark.line + 1 : 0, "", "YAML syntax: " + e.msg);
  }
  const ScenarioFields top(root, file_label, "");
  top.AllowOnly({"name", "description", "payload", "seed", "imu", "encoder", "lidar", "trajectory", "world"});
  Scenario s;
  s.file = file_label;
  s.world_file = file_label;
  s.text = yaml_text;
  s.name = top.Text("name", std::filesystem::path(file_label).stem().string());
  s.description = top.Text("description", "");
  const std::string payload = top.Text("payload", "");
  if (payload.empty()) throw ConfigError(file_label, top.LineOf("payload"), "payload", "missing (required)");
  s.payload = ResolvePayload(payload, base_dir);
  s.seed = top.Unsigned("seed", 1);
  if (top.Has("imu")) ReadImu(top.Map("imu"), &s.imu);
  if (top.Has("encoder")) ReadEncoder(top.Map("encoder"), &s);
  if (top.Has("lidar")) ReadLidar(top.Map("lidar"), &s);
  ReadTrajectory(top.Map("trajectory"), &s);
  s.world = top.Required("world");
  if (!s.world.IsSequence()) {
    throw ConfigError(file_label, YamlLine(s.world), "world", "must be a list of primitives");
  }
  return s;
}

Scenario LoadScenario(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ConfigError(file.string(), 0, "", "cannot read the scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  return ParseScenario(text.str(), file.string(), file.parent_path());
}

}  // namespace unimap::sim
