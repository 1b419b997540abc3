#include "EncoderSimulator.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace unimap::sim {
namespace {

// angle rounded to the nearest multiple of step (step 0: unchanged).
double RoundTo(double angle_rad, double step_rad) {
  return step_rad > 0.0 ? step_rad * std::round(angle_rad / step_rad) : angle_rad;
}

}  // namespace

EncoderSimulator::EncoderSimulator(const EncoderConfig& config) : config_(config) {
  if (!(std::isfinite(config_.rate_hz) && config_.rate_hz > 0.0)) {
    throw std::invalid_argument("encoder rate must be positive");
  }
  std::string why;
  if (!config_.motion.IsValid(&why)) throw std::invalid_argument("motor motion: " + why);
  if (!(std::isfinite(config_.resolution_rad) && config_.resolution_rad >= 0.0 &&
        config_.resolution_rad < 2.0 * M_PI)) {
    throw std::invalid_argument("encoder resolution must be in [0, 2 pi)");
  }
  if (!std::isfinite(config_.initial_angle_rad)) {
    throw std::invalid_argument("encoder initial angle must be finite");
  }
}

double EncoderSimulator::SampleTime(std::size_t k) const { return static_cast<double>(k) / config_.rate_hz; }

double EncoderSimulator::TrueAngle(double time_s) const {
  return config_.initial_angle_rad + config_.motion.EncoderAngleRad(time_s);
}

EncoderSample EncoderSimulator::Measure(double time_s) const {
  const double angle = TrueAngle(time_s);
  return EncoderSample{time_s, config_.motion.Wraps() ? Quantise(angle, config_.resolution_rad)
                                                      : RoundTo(angle, config_.resolution_rad)};
}

double EncoderSimulator::Wrap(double angle_rad) {
  double wrapped = std::fmod(angle_rad, 2.0 * M_PI);
  if (wrapped < 0.0) wrapped += 2.0 * M_PI;
  // fmod of a tiny negative angle plus 2 pi can round up to 2 pi itself.
  return wrapped >= 2.0 * M_PI ? 0.0 : wrapped;
}

double EncoderSimulator::Quantise(double angle_rad, double resolution_rad) {
  const double wrapped = Wrap(angle_rad);
  if (resolution_rad <= 0.0) return wrapped;
  return Wrap(RoundTo(wrapped, resolution_rad));
}

}  // namespace unimap::sim
