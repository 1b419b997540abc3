#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>

namespace unimap::sim {

// Typed, checked reading of one YAML map of a scenario file. Every failure
// throws ConfigError(file, line, dotted key, reason) with a 1-based line.
class ScenarioFields {
 public:
  // node: the map (ConfigError if it is not one); prefix: dotted path of the
  // map ("" at the top, "imu" for the imu block) used to name keys.
  ScenarioFields(const YAML::Node& node, std::string file, std::string prefix);

  // Rejects any key not in allowed (names the first unknown one and lists the allowed).
  void AllowOnly(std::initializer_list<const char*> allowed) const;
  bool Has(const std::string& key) const;

  // A number in [min, max]; the fallback when the key is absent.
  double Number(const std::string& key, double fallback, double min, double max) const;
  // The same, required.
  double RequiredNumber(const std::string& key, double min, double max) const;
  // A whole number in [min, max]; the fallback when absent.
  std::int64_t Integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) const;
  // A non-negative whole number, 64 bits (seeds); the fallback when absent.
  std::uint64_t Unsigned(const std::string& key, std::uint64_t fallback) const;
  // A plain scalar; the fallback when absent.
  std::string Text(const std::string& key, const std::string& fallback) const;
  // A list of three finite numbers; the fallback when absent.
  Eigen::Vector3d Vector3(const std::string& key, const Eigen::Vector3d& fallback) const;
  // A list of three finite numbers, required.
  Eigen::Vector3d RequiredVector3(const std::string& key) const;
  // A nested map, required (ConfigError when absent or not a map).
  ScenarioFields Map(const std::string& key) const;
  // The node under key, which must exist (not checked further).
  YAML::Node Required(const std::string& key) const;

  // The dotted name of a key of this map.
  std::string Name(const std::string& key) const;
  // 1-based line of a key of this map (of the map itself when absent).
  int LineOf(const std::string& key) const;
  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }

 private:
  // A scalar's number, or ConfigError.
  double ToNumber(const YAML::Node& value, const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string prefix_;
};

// 1-based line of a node (0 when yaml-cpp has no position for it).
int YamlLine(const YAML::Node& node);

}  // namespace unimap::sim
