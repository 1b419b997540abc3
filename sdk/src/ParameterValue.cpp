#include "unimap/ParameterValue.hpp"

#include <charconv>

namespace unimap {
namespace {

// Shortest text that reads back to the same double ("270", "0.1", "1e-06").
std::string FormatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

struct Formatter {
  std::string operator()(bool v) const { return v ? "true" : "false"; }
  std::string operator()(std::int64_t v) const { return std::to_string(v); }
  std::string operator()(double v) const { return FormatNumber(v); }
  std::string operator()(const std::string& v) const { return v; }
  std::string operator()(const std::vector<double>& v) const {
    std::string text = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) text += ", ";
      text += FormatNumber(v[i]);
    }
    return text + "]";
  }
};

struct Namer {
  std::string operator()(bool) const { return "bool"; }
  std::string operator()(std::int64_t) const { return "integer"; }
  std::string operator()(double) const { return "number"; }
  std::string operator()(const std::string&) const { return "string"; }
  std::string operator()(const std::vector<double>&) const { return "list of numbers"; }
};

}  // namespace

std::string ToString(const ParameterValue& value) { return std::visit(Formatter{}, value); }

std::string TypeName(const ParameterValue& value) { return std::visit(Namer{}, value); }

}  // namespace unimap
