#include "MinimumJerkProfile.hpp"

namespace unimap::sim {

double MinimumJerkProfile::Position(double u) {
  if (u <= 0.0) return 0.0;
  if (u >= 1.0) return 1.0;
  const double u3 = u * u * u;
  return u3 * (10.0 + u * (-15.0 + 6.0 * u));
}

double MinimumJerkProfile::Velocity(double u) {
  if (u <= 0.0 || u >= 1.0) return 0.0;
  const double u2 = u * u;
  return u2 * (30.0 + u * (-60.0 + 30.0 * u));
}

double MinimumJerkProfile::Acceleration(double u) {
  if (u <= 0.0 || u >= 1.0) return 0.0;
  return u * (60.0 + u * (-180.0 + 120.0 * u));
}

}  // namespace unimap::sim
