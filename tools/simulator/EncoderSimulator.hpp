#pragma once
#include <cstddef>

#include "unimap/EncoderSample.hpp"
#include "unimap/MotorMotion.hpp"

namespace unimap::sim {

// A motor read by an absolute encoder.
struct EncoderConfig {
  double rate_hz = 100.0;          // encoder samples per second (> 0)
  double resolution_rad = 0.0;     // quantisation step (0 = none; else 2 pi / counts)
  MotorMotion motion;              // how the reading moves (default: constant 30 rpm)
  double initial_angle_rad = 0.0;  // added to the motion's reading
};

// The encoder of a motor moving as MotorMotion states. The true (unwrapped)
// reading is
//   e(t) = e_0 + motion(t)   (constant rate: e_0 + 2 pi (rpm / 60) t);
// a sample reports it rounded to the nearest multiple of the resolution,
// wrapped to [0, 2 pi) for a spinning motor (MotorMotion::Wraps; wrapped
// again after rounding, so 2 pi reads 0) and as it is for a servo or a
// stepper. The motor angle follows from the payload's mount
// (theta = direction * e + offset).
class EncoderSimulator {
 public:
  // Throws std::invalid_argument for a non-positive rate, an invalid motion
  // (MotorMotion::IsValid) or a negative resolution.
  explicit EncoderSimulator(const EncoderConfig& config);

  // Time of sample k: k / rate_hz.
  double SampleTime(std::size_t k) const;
  // e(t), unwrapped and exact.
  double TrueAngle(double time_s) const;
  // The reading at time_s: e(t) quantised (and wrapped for a spinning motor).
  EncoderSample Measure(double time_s) const;

  // angle wrapped into [0, 2 pi).
  static double Wrap(double angle_rad);
  // angle wrapped, rounded to the nearest multiple of resolution_rad
  // (resolution 0: unchanged), wrapped again.
  static double Quantise(double angle_rad, double resolution_rad);

  const EncoderConfig& config() const { return config_; }

 private:
  EncoderConfig config_;
};

}  // namespace unimap::sim
