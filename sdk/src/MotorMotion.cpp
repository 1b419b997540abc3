#include "unimap/MotorMotion.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// The words of motor.motion, with their kinds.
const std::pair<const char*, MotorMotion::Kind> kKinds[] = {{"constant", MotorMotion::Kind::kConstant},
                                                            {"oscillating", MotorMotion::Kind::kOscillating},
                                                            {"stepping", MotorMotion::Kind::kStepping}};

const char* KindName(MotorMotion::Kind kind) {
  for (const auto& [name, k] : kKinds) {
    if (k == kind) return name;
  }
  return "constant";
}

// Position (deg above min) of a stepper going up, time_s after it left min:
// dwell, then a linear step, repeated; it stops at the top (span_deg).
double SteppingUp(const MotorMotion& m, double time_s, double span_deg) {
  const double unit_s = m.dwell_s + m.step_s;
  const double k = std::floor(time_s / unit_s);
  const double into_step = std::clamp((time_s - k * unit_s - m.dwell_s) / m.step_s, 0.0, 1.0);
  return std::min(span_deg, (k + into_step) * m.step_deg);
}

}  // namespace

double MotorMotion::EncoderAngleRad(double time_s) const {
  const double span_deg = max_deg - min_deg;
  switch (kind) {
    case Kind::kConstant:
      return 2.0 * M_PI * rate_rpm / 60.0 * time_s;
    case Kind::kOscillating: {
      const double phase = time_s / period_s - std::floor(time_s / period_s);  // [0, 1)
      const double up = profile == Profile::kSine ? 0.5 - 0.5 * std::cos(2.0 * M_PI * phase)
                                                  : (phase < 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase);
      return (min_deg + span_deg * up) * kDegToRad;
    }
    case Kind::kStepping: {
      // Up in ceil(span / step) steps (the last one stops at max), then down the same way.
      const double steps = std::ceil(span_deg / step_deg - 1e-9);
      const double half_s = steps * (dwell_s + step_s);
      const double t = std::fmod(time_s, 2.0 * half_s);
      const double deg =
          t < half_s ? min_deg + SteppingUp(*this, t, span_deg) : max_deg - SteppingUp(*this, t - half_s, span_deg);
      return deg * kDegToRad;
    }
  }
  return 0.0;
}

bool MotorMotion::IsValid(std::string* why) const {
  auto fail = [why](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (kind == Kind::kConstant) {
    if (!(std::isfinite(rate_rpm) && rate_rpm > 0.0)) return fail("motor.rate_rpm: must be positive");
    return true;
  }
  if (!(std::isfinite(min_deg) && std::isfinite(max_deg) && max_deg > min_deg)) {
    return fail("motor.max_deg: must be greater than motor.min_deg");
  }
  if (kind == Kind::kOscillating && !(std::isfinite(period_s) && period_s > 0.0)) {
    return fail("motor.period_s: must be positive");
  }
  if (kind == Kind::kStepping) {
    if (!(std::isfinite(step_deg) && step_deg > 0.0)) return fail("motor.step_deg: must be positive");
    if (!(std::isfinite(step_s) && step_s > 0.0)) return fail("motor.step_s: must be positive");
    if (!(std::isfinite(dwell_s) && dwell_s >= 0.0)) return fail("motor.dwell_s: must be >= 0");
  }
  return true;
}

void MotorMotion::AddTo(ParameterSet* set) const {
  set->Add({"motor.motion",
            "",
            "how the motor moves: constant (spins), oscillating (nods between min and max), stepping "
            "(steps between min and max); the simulator plays it, the mapper follows the encoder",
            std::string(KindName(kind)),
            0.0,
            0.0,
            {kKinds[0].first, kKinds[1].first, kKinds[2].first}});
  set->Add({"motor.rate_rpm", "", "constant: motor speed (rev/min)", rate_rpm, 0.1, 600.0, {}});
  set->Add({"motor.min_deg", "", "oscillating, stepping: lowest encoder reading (deg)", min_deg, -360.0, 360.0, {}});
  set->Add({"motor.max_deg", "", "oscillating, stepping: highest encoder reading (deg)", max_deg, -360.0, 360.0, {}});
  set->Add({"motor.period_s", "", "oscillating: one cycle min -> max -> min (s)", period_s, 0.01, 3600.0, {}});
  set->Add({"motor.profile",
            "",
            "oscillating: sine, or triangle (constant speed, instant reversal)",
            std::string(profile == Profile::kSine ? "sine" : "triangle"),
            0.0,
            0.0,
            {"sine", "triangle"}});
  set->Add({"motor.step_deg", "", "stepping: angle of one step (deg)", step_deg, 1e-4, 360.0, {}});
  set->Add({"motor.step_s", "", "stepping: time one step takes (s)", step_s, 1e-4, 60.0, {}});
  set->Add({"motor.dwell_s", "", "stepping: time at rest before each step (s)", dwell_s, 0.0, 60.0, {}});
}

MotorMotion MotorMotion::FromMap(const ParameterMap& map) {
  MotorMotion m;
  if (!map.Contains("motor.motion")) {
    if (!map.Contains("motor.rate_rpm")) {
      throw ConfigError("", 0, "motor.motion",
                        "the payload states no motor motion (motor.motion, or motor.rate_rpm for a constant rate)");
    }
    m.rate_rpm = map.GetDouble("motor.rate_rpm");
  } else {
    const std::string& word = map.GetString("motor.motion");
    const auto* found =
        std::find_if(std::begin(kKinds), std::end(kKinds), [&word](const auto& entry) { return word == entry.first; });
    if (found == std::end(kKinds)) {
      throw ConfigError("", 0, "motor.motion", "'" + word + "' is not constant, oscillating or stepping");
    }
    m.kind = found->second;
    auto number = [&map](const char* key, double fallback) {
      return map.Contains(key) ? map.GetDouble(key) : fallback;
    };
    m.rate_rpm = number("motor.rate_rpm", m.rate_rpm);
    m.min_deg = number("motor.min_deg", m.min_deg);
    m.max_deg = number("motor.max_deg", m.max_deg);
    m.period_s = number("motor.period_s", m.period_s);
    m.step_deg = number("motor.step_deg", m.step_deg);
    m.step_s = number("motor.step_s", m.step_s);
    m.dwell_s = number("motor.dwell_s", m.dwell_s);
    if (map.Contains("motor.profile")) {
      const std::string& profile = map.GetString("motor.profile");
      if (profile != "sine" && profile != "triangle") {
        throw ConfigError("", 0, "motor.profile", "'" + profile + "' is not sine or triangle");
      }
      m.profile = profile == "sine" ? Profile::kSine : Profile::kTriangle;
    }
  }
  std::string why;
  if (!m.IsValid(&why)) {
    const std::string key = why.substr(0, why.find(':'));
    throw ConfigError("", 0, key, why.substr(why.find(':') + 2));
  }
  return m;
}

}  // namespace unimap
