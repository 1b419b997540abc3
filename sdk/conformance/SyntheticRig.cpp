#include "SyntheticRig.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace unimap::conformance {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kDegToRad = M_PI / 180.0;

// Wraps an angle into [0, 2pi) or [-pi, pi).
double WrapAngle(double angle_rad, SyntheticRig::Wrap wrap) {
  if (wrap == SyntheticRig::Wrap::kZeroToTwoPi) {
    double wrapped = std::fmod(angle_rad, kTwoPi);
    if (wrapped < 0.0) wrapped += kTwoPi;
    return wrapped;
  }
  double wrapped = std::fmod(angle_rad + M_PI, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  return wrapped - M_PI;
}

}  // namespace

double SyntheticRig::EncoderAngle(double time_s) { return kMotorRateRadS * time_s + kEncoderPhaseRad; }

std::vector<EncoderSample> SyntheticRig::EncoderSamples(Wrap wrap, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> gap_s(0.001, 0.020);
  std::vector<EncoderSample> samples;
  double t = kEncoderStartS;
  while (t < kEncoderEndS) {
    samples.push_back({t, WrapAngle(EncoderAngle(t), wrap)});
    t += gap_s(rng);
  }
  samples.push_back({kEncoderEndS, WrapAngle(EncoderAngle(kEncoderEndS), wrap)});
  return samples;
}

std::vector<double> SyntheticRig::WrapTimes(Wrap wrap) {
  // The raw angle jumps where the unwrapped angle crosses 2pi k ([0, 2pi)) or
  // pi + 2pi k ([-pi, pi)): t_k = (crossing - phase) / rate.
  const double first_crossing = wrap == Wrap::kZeroToTwoPi ? 0.0 : M_PI;
  std::vector<double> times;
  for (int k = -2; k < 10; ++k) {
    const double t = (first_crossing + kTwoPi * k - kEncoderPhaseRad) / kMotorRateRadS;
    if (t > kEncoderStartS && t < kEncoderEndS) times.push_back(t);
  }
  return times;
}

EncoderTrack SyntheticRig::EncoderFor(const PayloadPlugin& plugin) {
  if (!plugin.UsesEncoder()) return EncoderTrack();
  return EncoderTrack(EncoderSamples(Wrap::kZeroToTwoPi, 7));
}

Eigen::Isometry3d SyntheticRig::WorldFromBody(double time_s) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 1.0).normalized();
  const double angular_rate_rad_s = 0.5;
  const Eigen::Vector3d velocity_m_s = Eigen::Vector3d(0.8, 0.6, 0.0);  // |v| = 1.0 m/s
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();
  T_world_body.linear() = Eigen::AngleAxisd(angular_rate_rad_s * time_s, axis).toRotationMatrix();
  T_world_body.translation() = velocity_m_s * time_s;
  return T_world_body;
}

RawScan SyntheticRig::Scan(std::size_t point_count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> time_s(kScanStartS, kScanEndS);
  std::uniform_real_distribution<double> range_m(5.0, 10.0);
  std::uniform_real_distribution<double> azimuth_rad(-60.0 * kDegToRad, 60.0 * kDegToRad);
  std::uniform_real_distribution<double> elevation_rad(-10.0 * kDegToRad, 10.0 * kDegToRad);

  std::vector<double> times(point_count);
  for (double& t : times) t = time_s(rng);
  std::sort(times.begin(), times.end());
  if (!times.empty()) {
    times.front() = kScanStartS;
    times.back() = kScanEndS;
  }
  RawScan scan;
  scan.start_time_s = kScanStartS;
  scan.end_time_s = kScanEndS;
  scan.has_point_time = true;
  for (double t : times) {
    const double r = range_m(rng);
    const double az = azimuth_rad(rng);
    const double el = elevation_rad(rng);
    Point p;
    p.position_m = r * Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    p.time_s = t;
    p.intensity = 1.0f;
    scan.points.push_back(p);
  }
  return scan;
}

std::vector<Eigen::Vector3d> SyntheticRig::ExpectedBodyPoints(const PayloadPlugin& plugin, const RawScan& scan,
                                                              const EncoderTrack& encoder) {
  const Eigen::Isometry3d T_body_world_end = WorldFromBody(scan.end_time_s).inverse();
  std::vector<Eigen::Vector3d> expected;
  expected.reserve(scan.points.size());
  for (const Point& p : scan.points) {
    const Eigen::Vector3d p_world =
        WorldFromBody(p.time_s) * (plugin.BodyFromLidarAt(encoder, p.time_s) * p.position_m);
    expected.push_back(T_body_world_end * p_world);
  }
  return expected;
}

}  // namespace unimap::conformance
