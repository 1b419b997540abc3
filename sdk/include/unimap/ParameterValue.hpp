#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "unimap/Export.hpp"

namespace unimap {

// One configuration value: a flag, a whole number, a real number, a word, or
// a fixed-length list of real numbers (vectors, extrinsics).
using ParameterValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>>;

// "true", "40", "0.05", "rotating_2d", "[0, 0, 0.1]"; numbers round-trip.
UNIMAP_SDK_API std::string ToString(const ParameterValue& value);

// "bool", "integer", "number", "string", "list of numbers".
UNIMAP_SDK_API std::string TypeName(const ParameterValue& value);

}  // namespace unimap
