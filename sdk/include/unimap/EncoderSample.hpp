#pragma once

namespace unimap {

// One motor encoder reading: the raw angle, in any wrap convention
// ([0, 2pi), [-pi, pi), ...).
struct EncoderSample {
  double time_s = 0.0;
  double angle_rad = 0.0;
};

}  // namespace unimap
