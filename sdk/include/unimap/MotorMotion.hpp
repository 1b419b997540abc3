#pragma once
#include <string>

#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap {

// How a payload's motor moves, as its encoder reads it: a motor spinning at a
// constant rate, a servo nodding between two angles, or a stepper stepping
// between two angles and dwelling at each step. The mapper never assumes it
// (it follows the encoder); the simulator plays it back and a user reads
// what the rig does. Keys (AddTo / FromMap):
//   motor.motion         "constant" | "oscillating" | "stepping"
//   motor.rate_rpm       constant: revolutions per minute
//   motor.min_deg, motor.max_deg   oscillating and stepping: the reading's range
//   motor.period_s       oscillating: one full cycle, min -> max -> min
//   motor.profile        oscillating: "sine" or "triangle" (constant angular speed, instant reversal)
//   motor.step_deg, motor.step_s, motor.dwell_s   stepping: each step turns
//                        step_deg in step_s after a dwell of dwell_s, from
//                        min to max and back
struct UNIMAP_SDK_API MotorMotion {
  enum class Kind { kConstant, kOscillating, kStepping };
  enum class Profile { kSine, kTriangle };

  Kind kind = Kind::kConstant;
  double rate_rpm = 30.0;  // constant: speed (rev/min, > 0)
  double min_deg = -45.0;  // oscillating, stepping: lowest reading (deg)
  double max_deg = 45.0;   // ... highest reading (deg, > min_deg)
  double period_s = 2.0;   // oscillating: min -> max -> min (s, > 0)
  Profile profile = Profile::kSine;
  double step_deg = 0.3;  // stepping: one step (deg, > 0)
  double step_s = 0.01;   // stepping: time a step takes (s, > 0)
  double dwell_s = 0.1;   // stepping: time at rest before each step (s, >= 0)

  // The true encoder reading (rad, unwrapped) at time_s >= 0: constant
  // starts at 0 and grows by 2 pi rate_rpm / 60 per second; oscillating and
  // stepping start at min_deg (the sine profile is
  // mid - half_range cos(2 pi t / period_s)).
  double EncoderAngleRad(double time_s) const;
  // True when the encoder wraps its reading into one turn (a spinning
  // motor); a servo or stepper reports its angle as it is.
  bool Wraps() const { return kind == Kind::kConstant; }
  // True when the fields are in range; otherwise false with the reason
  // (naming the key) in *why when why is not null.
  bool IsValid(std::string* why) const;

  // Adds every key above, with this object's values as defaults.
  void AddTo(ParameterSet* set) const;
  // Reads the keys; a map without "motor.motion" but with "motor.rate_rpm"
  // is a constant-rate motor (payloads that predate motor.motion). Throws
  // ConfigError naming the key when neither is present or a value is out
  // of range.
  static MotorMotion FromMap(const ParameterMap& map);
};

}  // namespace unimap
