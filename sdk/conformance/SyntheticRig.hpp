#pragma once
// Closed-form synthetic motion and sensor data for the conformance suite
// (private to libunimap_conformance; not installed).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/EncoderSample.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/PayloadPlugin.hpp"
#include "unimap/RawScan.hpp"

namespace unimap::conformance {

// A synthetic rig whose every quantity has an analytic value:
//   encoder(t)      = kMotorRateRadS * t + kEncoderPhaseRad (constant-rate motor),
//   T_world_body(t) = (exp([w]x t), v t) (constant angular and linear velocity).
// Encoder samples cover [kEncoderStartS, kEncoderEndS]; scans lie in
// [kScanStartS, kScanEndS], well inside that coverage.
class SyntheticRig {
 public:
  // How raw encoder angles are wrapped before the plugin sees them.
  enum class Wrap { kZeroToTwoPi, kMinusPiToPi };

  static constexpr double kMotorRateRadS = 3.3;    // encoder angle rate (rad/s)
  static constexpr double kEncoderPhaseRad = 0.4;  // encoder angle at t = 0 (rad)
  static constexpr double kEncoderStartS = 0.0;    // first encoder sample (s)
  static constexpr double kEncoderEndS = 2.0;      // last encoder sample (s)
  static constexpr double kScanStartS = 0.9;       // synthetic scan window start (s)
  static constexpr double kScanEndS = 1.0;         // synthetic scan window end (s)

  // Unwrapped analytic encoder angle (rad) at time_s.
  static double EncoderAngle(double time_s);
  // Samples of EncoderAngle over [kEncoderStartS, kEncoderEndS] (both ends
  // included) at irregular spacing (random gaps of 1-20 ms drawn from seed),
  // raw angles wrapped as asked.
  static std::vector<EncoderSample> EncoderSamples(Wrap wrap, std::uint32_t seed);
  // Times inside the encoder coverage where the wrapped raw angle jumps.
  static std::vector<double> WrapTimes(Wrap wrap);
  // The encoder a payload needs for the synthetic scans: a [0, 2pi) track
  // for a payload with a motor, an empty track otherwise.
  static EncoderTrack EncoderFor(const PayloadPlugin& plugin);

  // T_world_body(t) = (exp([w]x t), v t): w = 0.5 rad/s about a tilted axis,
  // v = 1.0 m/s along a fixed direction.
  static Eigen::Isometry3d WorldFromBody(double time_s);

  // A scan over [kScanStartS, kScanEndS] with per-point times: point_count
  // returns at random ascending times (the first at the start, the last at
  // the end), in the LiDAR frame at 5-10 m range, azimuth within +-60 deg
  // of +x and elevation within +-10 deg, drawn from seed.
  static RawScan Scan(std::size_t point_count, std::uint32_t seed);

  // The analytic deskew of every point of scan, using the plugin's own mount:
  //   p_world = T_world_body(t_i) * T_body_lidar(t_i) * p_lidar,
  //   p_body  = T_world_body(t_end)^-1 * p_world.
  static std::vector<Eigen::Vector3d> ExpectedBodyPoints(const PayloadPlugin& plugin, const RawScan& scan,
                                                         const EncoderTrack& encoder);
};

}  // namespace unimap::conformance
