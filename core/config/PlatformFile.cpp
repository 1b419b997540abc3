#include "PlatformFile.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <utility>

#include <yaml-cpp/yaml.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

// 1-based line of a yaml-cpp position; 0 when it has none.
int LineOf(const YAML::Mark& mark) { return mark.line >= 0 ? mark.line + 1 : 0; }

// 1-based line of a node; 0 when yaml-cpp has no position for it.
int LineOf(const YAML::Node& node) { return LineOf(node.Mark()); }

// True for a scalar that quotes or a !!str tag make a string whatever it reads.
bool IsForcedString(const YAML::Node& node) {
  const std::string& tag = node.Tag();
  return tag == "!" || tag == "tag:yaml.org,2002:str";
}

// How a node is called in messages.
std::string KindOf(const YAML::Node& node) {
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  if (node.IsNull()) return "nothing";
  return "'" + node.Scalar() + "'";
}

// A list of numbers from a YAML sequence; throws ConfigError naming the first
// element that is not a plain number.
std::vector<double> ListOf(const YAML::Node& sequence, const std::string& file, const std::string& key, int line) {
  std::vector<double> numbers;
  numbers.reserve(sequence.size());
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    const YAML::Node element = sequence[i];
    ParameterValue parsed = false;  // anything but a number: rejected below
    if (element.IsScalar() && !IsForcedString(element)) parsed = ParseScalar(element.Scalar());
    if (const auto* whole = std::get_if<std::int64_t>(&parsed)) {
      numbers.push_back(static_cast<double>(*whole));
    } else if (const auto* real = std::get_if<double>(&parsed)) {
      numbers.push_back(*real);
    } else {
      const int element_line = LineOf(element);
      throw ConfigError(file, element_line > 0 ? element_line : line, key,
                        "expected a list of numbers, but element " + std::to_string(i + 1) + " is " + KindOf(element));
    }
  }
  return numbers;
}

// The value of a leaf (non-map) node; throws ConfigError when it is empty or
// a list of something other than numbers.
ParameterValue ValueOf(const YAML::Node& node, const std::string& file, const std::string& key, int line) {
  if (node.IsNull()) throw ConfigError(file, line, key, "no value given");
  if (node.IsSequence()) return ListOf(node, file, key, line);
  if (IsForcedString(node)) return node.Scalar();
  return ParseScalar(node.Scalar());
}

// Most parameters a platform file may set: a bound on what YAML aliases
// (`*a` repeating a group) can expand to.
constexpr std::size_t kMaxOverrides = 10000;

// Appends the leaves of a `parameters:` map (recursively, keys joined with
// '.') to *out; first_line remembers where each key was set to catch
// duplicates; groups holds the maps being walked (an alias to one of them
// is a cycle, which would recurse forever).
void CollectOverrides(const YAML::Node& map, const std::string& prefix, const std::string& file,
                      std::vector<ParameterOverride>* out, std::map<std::string, int>* first_line,
                      std::vector<YAML::Node>* groups) {
  groups->push_back(map);
  for (auto it = map.begin(); it != map.end(); ++it) {
    const YAML::Node key_node = it->first;
    const YAML::Node value_node = it->second;
    const int line = LineOf(key_node);
    if (!key_node.IsScalar() || key_node.Scalar().empty()) {
      throw ConfigError(file, line, prefix, "a parameter name must be a plain word, got " + KindOf(key_node));
    }
    const std::string key = prefix.empty() ? key_node.Scalar() : prefix + "." + key_node.Scalar();
    for (const YAML::Node& group : *groups) {
      if (value_node.is(group)) {
        throw ConfigError(file, line, key, "a YAML alias refers to a group that contains it (a cycle)");
      }
    }
    if (value_node.IsMap()) {
      if (value_node.size() == 0) throw ConfigError(file, line, key, "empty group: no value given");
      CollectOverrides(value_node, key, file, out, first_line, groups);
      continue;
    }
    ParameterValue value = ValueOf(value_node, file, key, line);
    const auto [previous, inserted] = first_line->emplace(key, line);
    if (!inserted) {
      throw ConfigError(file, line, key, "set twice (first on line " + std::to_string(previous->second) + ")");
    }
    if (out->size() == kMaxOverrides) {
      throw ConfigError(file, line, key,
                        "more than " + std::to_string(kMaxOverrides) + " parameters (YAML aliases expanding?)");
    }
    out->push_back(ParameterOverride{key, std::move(value), line});
  }
  groups->pop_back();
}

// Scanners for the two number forms below (std::regex recursed once per
// character and overflowed the stack on a 300,000-digit value).
// Skips the digits from *i on; returns how many there were.
std::size_t SkipDigits(const std::string& text, std::size_t* i) {
  const std::size_t start = *i;
  while (*i < text.size() && text[*i] >= '0' && text[*i] <= '9') ++*i;
  return *i - start;
}
// [+-]?[0-9]+
bool IsInteger(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  return SkipDigits(text, &i) > 0 && i == text.size();
}
// [+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?
bool IsDecimal(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  const std::size_t whole = SkipDigits(text, &i);
  std::size_t fraction = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    fraction = SkipDigits(text, &i);
  }
  if (whole == 0 && fraction == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (SkipDigits(text, &i) == 0) return false;
  }
  return i == text.size();
}

}  // namespace

ParameterValue ParseScalar(const std::string& text) {
  if (IsInteger(text)) {
    errno = 0;
    char* end = nullptr;
    const long long whole = std::strtoll(text.c_str(), &end, 10);
    if (errno != ERANGE && end == text.c_str() + text.size()) {
      return static_cast<std::int64_t>(whole);
    }
    // Too large for int64: falls through to a (finite) double.
  }
  if (IsDecimal(text)) {
    errno = 0;
    char* end = nullptr;
    const double real = std::strtod(text.c_str(), &end);
    if (errno != ERANGE && end == text.c_str() + text.size()) return real;
  }
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return text;
}

PlatformFile PlatformFile::Parse(const std::string& yaml_text, const std::string& file_label) {
  PlatformFile result;
  result.file_ = file_label;
  const std::string& file = result.file_;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    if (root.IsNull()) {
      throw ConfigError(file, 0, "plugin", "missing 'plugin': the file is empty");
    }
    if (!root.IsMap()) {
      throw ConfigError(file, LineOf(root), "",
                        "expected a map with the keys 'plugin' and 'parameters', got " + KindOf(root));
    }
    std::map<std::string, int> top_lines;        // top-level key -> first line
    std::map<std::string, int> parameter_lines;  // dotted key -> first line
    std::map<std::string, int> mapper_lines;     // the same for `mapper:`
    for (auto it = root.begin(); it != root.end(); ++it) {
      const YAML::Node key_node = it->first;
      const YAML::Node value_node = it->second;
      const int line = LineOf(key_node);
      const std::string key = key_node.IsScalar() ? key_node.Scalar() : std::string();
      if (key != "plugin" && key != "parameters" && key != "mapper") {
        throw ConfigError(file, line, key, "unknown top-level key; expected 'plugin', 'parameters' or 'mapper'");
      }
      const auto [previous, inserted] = top_lines.emplace(key, line);
      if (!inserted) {
        throw ConfigError(file, line, key, "set twice (first on line " + std::to_string(previous->second) + ")");
      }
      if (key == "plugin") {
        if (!value_node.IsScalar() || value_node.Scalar().empty()) {
          throw ConfigError(file, line, key,
                            "expected a payload name or a plugin library path, got " + KindOf(value_node));
        }
        result.plugin_ = value_node.Scalar();
        result.plugin_line_ = line;
      } else if (key == "mapper") {
        if (value_node.IsNull()) continue;  // nothing under it: the defaults
        if (!value_node.IsMap()) {
          throw ConfigError(file, line, key, "expected a map of mapper settings, got " + KindOf(value_node));
        }
        std::vector<YAML::Node> groups;
        // Collected under "mapper." so that errors name the full key; kept below it.
        CollectOverrides(value_node, key, file, &result.mapper_settings_, &mapper_lines, &groups);
        for (ParameterOverride& setting : result.mapper_settings_) setting.key.erase(0, key.size() + 1);
      } else if (!value_node.IsNull()) {  // `parameters:` with nothing under it overrides nothing
        if (!value_node.IsMap()) {
          throw ConfigError(file, line, key, "expected a map of parameter overrides, got " + KindOf(value_node));
        }
        std::vector<YAML::Node> groups;
        CollectOverrides(value_node, "", file, &result.overrides_, &parameter_lines, &groups);
      }
    }
    if (top_lines.count("plugin") == 0) {
      throw ConfigError(file, 0, "plugin", "missing 'plugin': name the payload plugin or its library path");
    }
  } catch (const YAML::Exception& e) {
    throw ConfigError(file, LineOf(e.mark), "", "YAML syntax error: " + e.msg);
  }
  return result;
}

PlatformFile PlatformFile::Read(const std::filesystem::path& file) {
  const std::string label = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw ConfigError(label, 0, "", "platform file not found");
  }
  if (std::filesystem::is_directory(file, ec)) {
    throw ConfigError(label, 0, "", "is a directory, not a platform file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open()) throw ConfigError(label, 0, "", "cannot open the platform file");
  std::ostringstream text;
  text << in.rdbuf();  // an empty file leaves text empty (and its failbit set), which is fine
  if (in.bad()) throw ConfigError(label, 0, "", "cannot read the platform file");
  return Parse(text.str(), label);
}

}  // namespace unimap
