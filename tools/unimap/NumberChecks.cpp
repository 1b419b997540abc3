#include "NumberChecks.hpp"

#include <cmath>
#include <string>

namespace unimap::cli {
namespace {

// A validator accepting a finite number for which keep(value) holds.
CLI::Validator FiniteWhere(bool (*keep)(double), const std::string& name, const std::string& rule) {
  return CLI::Validator(
      [keep, rule](std::string& text) -> std::string {
        double value = 0.0;
        std::size_t used = 0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size()) return "'" + text + "' is not a number";
        if (!std::isfinite(value) || !keep(value)) return "'" + text + "' is not " + rule;
        return {};
      },
      name);
}

}  // namespace

CLI::Validator FinitePositive() {
  return FiniteWhere([](double v) { return v > 0.0; }, "FINITE > 0", "a finite number > 0");
}

CLI::Validator FiniteNonNegative() {
  return FiniteWhere([](double v) { return v >= 0.0; }, "FINITE >= 0", "a finite number >= 0");
}

}  // namespace unimap::cli
