#pragma once
// Number formatting shared by the command-line output.
#include <iomanip>
#include <sstream>
#include <string>

namespace unimap::cli {

// value with exactly `digits` decimals ("0.0850").
inline std::string Fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace unimap::cli
