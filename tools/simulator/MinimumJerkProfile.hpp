#pragma once

namespace unimap::sim {

// The minimum-jerk rest-to-rest profile on u in [0, 1] (Flash & Hogan):
//   s(u) = 10 u^3 - 15 u^4 + 6 u^5,
// s(0) = 0, s(1) = 1, and s', s'' vanish at both ends, so a motion built from
// such pieces has continuous velocity and acceleration. Derivatives are with
// respect to u; divide by T, T^2 for a piece of duration T.
class MinimumJerkProfile {
 public:
  // s(u), clamped to 0 below u = 0 and to 1 above u = 1.
  static double Position(double u);
  // ds/du (0 outside [0, 1]).
  static double Velocity(double u);
  // d2s/du2 (0 outside [0, 1]).
  static double Acceleration(double u);

  // max ds/du, reached at u = 1/2: 15/8.
  static constexpr double kPeakVelocity = 1.875;
  // max |d2s/du2|, reached at u = 1/2 -+ sqrt(3)/6: 10/sqrt(3).
  static constexpr double kPeakAcceleration = 5.773502691896258;
};

}  // namespace unimap::sim
