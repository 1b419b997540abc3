// nodding_2d: an out-of-tree unimap payload plugin, built only on the
// installed SDK (find_package(unimap)). A 2D line scanner (Hokuyo UTM-30LX
// class: 40 Hz, 270 deg, 1081 beams, 0.1..30 m) on a servo that tilts it
// +-45 deg about the body's y axis; the encoder reports the servo angle
// (no wrap-around). The SDK does the heavy lifting:
//   CoreParameters   the paper's per-platform parameters (Table 1),
//   MotorMount       T_body_lidar(theta) = T_body_motor * Rot(axis, theta) * T_motor_lidar,
//   MotorMotion      how the servo nods (what `unimap simulate` plays back),
//   EncoderTrack     servo angle at any time (linear interpolation),
//   LineScanToRawScan beam firing times for lines that come without them,
//   DeskewScan       rigid-body deskew to the line's end time.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <unimap/CoreParameters.hpp>
#include <unimap/Deskew.hpp>
#include <unimap/Errors.hpp>
#include <unimap/LineScan.hpp>
#include <unimap/MotorMotion.hpp>
#include <unimap/MotorMount.hpp>
#include <unimap/PayloadPlugin.hpp>
#include <unimap/PluginExport.hpp>

namespace nodding {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr const char* kScanRate = "lidar.scan_rate_hz";
constexpr const char* kFov = "lidar.fov_deg";
constexpr const char* kBeams = "lidar.beams";
constexpr const char* kMinRange = "lidar.min_range_m";
constexpr const char* kMaxRange = "lidar.max_range_m";

// The line scanner on the servo, as the "lidar.*" keys describe it.
struct LineScanner {
  double scan_rate_hz = 40.0;             // lines per second (mirror revolutions per second)
  double fov_deg = 270.0;                 // first to last beam, centred on the scanner's +x
  std::int64_t beams = 1081;              // beams per line, first and last included
  unimap::RangeLimits limits{0.1, 30.0};  // valid returns (m)
};

// Default geometry: the servo 0.1 m ahead of and 0.05 m above the body
// origin, tilting about its y axis (= body y); the scanner 0.03 m further up,
// its scan plane horizontal and centred on body +x at servo angle 0.
unimap::MotorMount DefaultServo() {
  unimap::MotorMount servo;
  servo.body_motor.translation_m = Eigen::Vector3d(0.1, 0.0, 0.05);
  servo.motor_lidar.translation_m = Eigen::Vector3d(0.0, 0.0, 0.03);
  servo.axis_motor = Eigen::Vector3d::UnitY();
  servo.encoder_offset_deg = 0.0;
  servo.encoder_direction = 1;
  return servo;
}

// The servo nods between -45 and +45 deg, one cycle (down -> up -> down)
// every 2 s, slowing at the ends like a hobby servo (sine).
unimap::MotorMotion DefaultNod() {
  unimap::MotorMotion nod;
  nod.kind = unimap::MotorMotion::Kind::kOscillating;
  nod.min_deg = -45.0;
  nod.max_deg = 45.0;
  nod.period_s = 2.0;
  nod.profile = unimap::MotorMotion::Profile::kSine;
  return nod;
}

// Table 1 for a nodding Hokuyo: one nod up (1 s at 0.5 Hz) = 40 lines.
unimap::CoreParameters DefaultCore() {
  unimap::CoreParameters core;
  core.scans_per_3d_scan = 40;
  core.scans_3d_per_submap = 20;
  core.scans_3d_per_optimization = 10;
  core.sigma_accel_m_s2 = 0.02;
  core.sigma_gyro_rad_s = 0.002;
  core.distance_map_resolution_m = 0.1;
  core.distance_map_max_range_m = 30.0;  // the scanner's range: far returns hold a corridor's long axis
  return core;
}

void AddScannerKeys(const LineScanner& s, unimap::ParameterSet* set) {
  set->Add({kScanRate, "", "lines per second (Hz)", s.scan_rate_hz, 0.1, 1000.0, {}});
  set->Add({kFov, "", "angle from the first to the last beam, centred on +x (deg)", s.fov_deg, 1.0, 360.0, {}});
  set->Add({kBeams, "", "beams per line, first and last included (count)", s.beams, 2, 100000, {}});
  set->Add({kMinRange, "", "shortest valid return (m)", s.limits.min_range_m, 0.0, 1000.0, {}});
  set->Add({kMaxRange, "", "longest valid return (m)", s.limits.max_range_m, 0.01, 1000.0, {}});
}

LineScanner ScannerFromMap(const unimap::ParameterMap& map) {
  LineScanner s;
  s.scan_rate_hz = map.GetDouble(kScanRate);
  s.fov_deg = map.GetDouble(kFov);
  s.beams = map.GetInt(kBeams);
  s.limits.min_range_m = map.GetDouble(kMinRange);
  s.limits.max_range_m = map.GetDouble(kMaxRange);
  if (!(s.limits.max_range_m > s.limits.min_range_m)) {
    throw unimap::ConfigError("", 0, kMaxRange, "must be greater than lidar.min_range_m");
  }
  return s;
}

// The line the scanner reported, rebuilt from a scan without point times:
// every point is a return of the beam nearest to its azimuth,
//   k_i = round((atan2(y_i, x_i) - angle_min) / angle_increment),
// beam k fires at start_time_s + k * time_increment. Throws InputError for a
// point off the scan plane, outside the field of view, or sharing a beam.
unimap::LineScan RebuildLine(const unimap::RawScan& scan, const LineScanner& s) {
  if (scan.points.empty()) throw unimap::InputError("empty scan (no points)");
  unimap::LineScan line;
  line.start_time_s = scan.start_time_s;
  line.angle_min_rad = -0.5 * s.fov_deg * kDegToRad;
  line.angle_increment_rad = s.fov_deg * kDegToRad / static_cast<double>(s.beams - 1);
  line.time_increment_s = line.angle_increment_rad / (2.0 * M_PI * s.scan_rate_hz);
  line.range_min_m = s.limits.min_range_m;
  line.range_max_m = s.limits.max_range_m;
  line.ranges_m.assign(static_cast<std::size_t>(s.beams), std::nanf(""));
  line.intensities.assign(static_cast<std::size_t>(s.beams), 0.0f);
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3d& p = scan.points[i].position_m;
    const std::string label = "point " + std::to_string(i) + ": ";
    if (!p.allFinite()) throw unimap::InputError(label + "non-finite coordinate");
    if (std::fabs(p.z()) > 1e-6 * std::max(1.0, p.norm())) {
      throw unimap::InputError(label + "off the scan plane (z != 0)");
    }
    const double beam = std::round((std::atan2(p.y(), p.x()) - line.angle_min_rad) / line.angle_increment_rad);
    if (!(beam >= 0.0 && beam < static_cast<double>(s.beams))) {
      throw unimap::InputError(label + "outside the field of view");
    }
    const auto k = static_cast<std::size_t>(beam);
    if (!std::isnan(line.ranges_m[k])) {
      throw unimap::InputError(label + "second return for beam " + std::to_string(k));
    }
    line.ranges_m[k] = static_cast<float>(p.norm());
    line.intensities[k] = scan.points[i].intensity;
  }
  return line;
}

}  // namespace

// The nodding_2d payload: T_body_lidar(t) = T_body_servo * Rot(y, theta(t)) *
// T_servo_lidar with theta(t) = direction * encoder(t) + offset.
class NoddingPlugin final : public unimap::PayloadPlugin {
 public:
  // Configured with Defaults().
  NoddingPlugin() { Configure(Defaults().DefaultMap()); }

  std::string Name() const override { return "nodding_2d"; }

  std::string Description() const override {
    return "2D line scanner (Hokuyo UTM-30LX class: 40 Hz, 270 deg) on a servo nodding +-45 deg "
           "about body y; the encoder reports the servo angle";
  }

  // CoreParameters + MotorMount keys (extrinsic.body_motor.*,
  // extrinsic.motor_lidar.*, motor.*) + MotorMotion keys (motor.motion, ...)
  // + lidar.*.
  unimap::ParameterSet Defaults() const override {
    unimap::ParameterSet set;
    DefaultCore().AddTo(&set);
    DefaultServo().AddTo(&set);
    DefaultNod().AddTo(&set);
    AddScannerKeys(LineScanner{}, &set);
    return set;
  }

  // Validates every key, reads everything, then applies: a ConfigError
  // leaves the previous configuration in effect.
  void Configure(const unimap::ParameterMap& parameters) override {
    Defaults().Validate(parameters);
    const unimap::CoreParameters core = unimap::CoreParameters::FromMap(parameters);
    const unimap::MotorMount servo = unimap::MotorMount::FromMap(parameters);
    unimap::MotorMotion::FromMap(parameters);  // checked; the mapper follows the encoder
    const LineScanner scanner = ScannerFromMap(parameters);
    core_ = core;
    servo_ = servo;
    scanner_ = scanner;
  }

  bool UsesEncoder() const override { return true; }

  // theta(t) from the interpolated servo reading; InputError outside coverage.
  double MotorAngleAt(const unimap::EncoderTrack& encoder, double time_s) const override {
    return servo_.MotorAngle(encoder.AngleAt(time_s));
  }

  Eigen::Isometry3d BodyFromLidarAt(const unimap::EncoderTrack& encoder, double time_s) const override {
    return servo_.BodyFromLidar(MotorAngleAt(encoder, time_s));
  }

  // Lines with point times are deskewed as they are; lines without are
  // rebuilt and converted by the SDK (beam times, range limits) first.
  unimap::BodyScan Deskew(const unimap::RawScan& scan, const unimap::EncoderTrack& encoder,
                          const unimap::MotionQuery& T_world_body_at) const override {
    const unimap::MountQuery T_body_lidar_at = [this, &encoder](double time_s) {
      return BodyFromLidarAt(encoder, time_s);
    };
    if (scan.has_point_time) {
      return unimap::DeskewScan(scan, T_body_lidar_at, T_world_body_at, scanner_.limits);
    }
    const unimap::LineScan line = RebuildLine(scan, scanner_);
    const unimap::LineScanConversion converted = unimap::LineScanToRawScan(line);
    // LineScanToRawScan counts empty beams with the invalid returns; only the latter are drops.
    const std::size_t out_of_range = converted.dropped - (line.ranges_m.size() - scan.points.size());
    if (converted.scan.points.empty()) {
      unimap::BodyScan none;
      none.reference_time_s = converted.scan.end_time_s;
      none.dropped_out_of_range = out_of_range;
      return none;
    }
    unimap::BodyScan body = unimap::DeskewScan(converted.scan, T_body_lidar_at, T_world_body_at, scanner_.limits);
    body.dropped_out_of_range += out_of_range;
    return body;
  }

 private:
  unimap::CoreParameters core_;  // the paper's parameters, as configured
  unimap::MotorMount servo_;     // servo geometry and encoder convention
  LineScanner scanner_;          // beam layout and range limits
};

}  // namespace nodding

UNIMAP_EXPORT_PAYLOAD_PLUGIN(nodding::NoddingPlugin)
