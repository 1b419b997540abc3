#pragma once
// Command-line checks for numbers that CLI11's own let through: its
// PositiveNumber and NonNegativeNumber accept NaN (every comparison with NaN
// is false) and infinity.
#include <CLI/CLI.hpp>

namespace unimap::cli {

// A finite number > 0.
CLI::Validator FinitePositive();
// A finite number >= 0.
CLI::Validator FiniteNonNegative();

}  // namespace unimap::cli
