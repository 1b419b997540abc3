#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace unimap::cli {

// A JSON object built key by key, in insertion order (for run.json); a
// value may be a nested object.
class JsonObject {
 public:
  void Add(const std::string& key, double value) { Raw(key, Number(value)); }
  void Add(const std::string& key, std::size_t value) { Raw(key, std::to_string(value)); }
  void Add(const std::string& key, bool value) { Raw(key, value ? "true" : "false"); }
  void Add(const std::string& key, const std::string& value) { Raw(key, Quote(value)); }
  void Add(const std::string& key, const char* value) { Raw(key, Quote(value)); }
  void Add(const std::string& key, const std::vector<std::string>& values) {
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + Quote(values[i]);
    Raw(key, text + "]");
  }
  // Adds a nested object.
  void Add(const std::string& key, const JsonObject& object) { Raw(key, object.ToString()); }

  // Two spaces per level; a nested object's lines are indented with its field.
  std::string ToString() const {
    std::string text = "{\n";
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      text += "  " + Quote(fields_[i].first) + ": " + Indented(fields_[i].second);
      text += i + 1 < fields_.size() ? ",\n" : "\n";
    }
    return text + "}";
  }

 private:
  void Raw(const std::string& key, std::string value) { fields_.emplace_back(key, std::move(value)); }
  static std::string Number(double v) {
    if (!std::isfinite(v)) return "null";
    std::ostringstream out;
    out.precision(10);
    out << v;
    return out.str();
  }
  // Each line after the first indented by two more spaces (values hold no
  // raw newline but those of nested objects: Quote replaces control characters).
  static std::string Indented(const std::string& value) {
    std::string out;
    for (const char c : value) {
      out += c;
      if (c == '\n') out += "  ";
    }
    return out;
  }
  static std::string Quote(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
      if (c == '"' || c == '\\') {
        out += '\\';
        out += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        out += ' ';
      } else {
        out += c;
      }
    }
    return out + "\"";
  }
  std::vector<std::pair<std::string, std::string>> fields_;
};

}  // namespace unimap::cli
