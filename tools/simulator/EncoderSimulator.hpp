#pragma once
#include <cstddef>

#include "unimap/EncoderSample.hpp"

namespace unimap::sim {

// A motor turning at a constant rate, read by an absolute encoder.
struct EncoderConfig {
  double rate_hz = 100.0;          // encoder samples per second (> 0)
  double resolution_rad = 0.0;     // quantisation step (0 = none; else 2 pi / counts)
  double motor_rate_rpm = 30.0;    // the reading advances at 2 pi rpm / 60 rad/s (> 0)
  double initial_angle_rad = 0.0;  // reading at time 0
};

// The encoder of a constant-rate motor. The true (unwrapped) reading is
//   e(t) = e_0 + 2 pi (rpm / 60) t;
// a sample reports it wrapped to [0, 2 pi) and rounded to the nearest
// multiple of the resolution (wrapped again, so 2 pi reads 0). The motor
// angle follows from the payload's mount (theta = direction * e + offset).
class EncoderSimulator {
 public:
  // Throws std::invalid_argument for a non-positive rate or motor rate, or a
  // negative resolution.
  explicit EncoderSimulator(const EncoderConfig& config);

  // Time of sample k: k / rate_hz.
  double SampleTime(std::size_t k) const;
  // e(t), unwrapped and exact.
  double TrueAngle(double time_s) const;
  // The reading at time_s: e(t) wrapped and quantised.
  EncoderSample Measure(double time_s) const;

  // angle wrapped into [0, 2 pi).
  static double Wrap(double angle_rad);
  // angle wrapped, rounded to the nearest multiple of resolution_rad
  // (resolution 0: unchanged), wrapped again.
  static double Quantise(double angle_rad, double resolution_rad);

  const EncoderConfig& config() const { return config_; }

 private:
  EncoderConfig config_;
  double rate_rad_s_;  // de/dt
};

}  // namespace unimap::sim
