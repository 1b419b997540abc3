#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "unimap/Export.hpp"
#include "unimap/ParameterValue.hpp"

namespace unimap {

// Effective parameters by dotted key ("extrinsic.body_lidar.rpy_deg"). The
// typed getters throw ConfigError naming the key when it is missing or of
// another type; an integer is accepted where a number is asked for.
class UNIMAP_SDK_API ParameterMap {
 public:
  // Sets (or replaces) one value.
  void Set(const std::string& key, ParameterValue value);
  // True when the key has a value.
  bool Contains(const std::string& key) const;
  // The value of a key; throws ConfigError if missing.
  const ParameterValue& At(const std::string& key) const;

  bool GetBool(const std::string& key) const;
  std::int64_t GetInt(const std::string& key) const;
  double GetDouble(const std::string& key) const;
  const std::string& GetString(const std::string& key) const;
  // A list of exactly expected_size numbers.
  std::vector<double> GetVector(const std::string& key, std::size_t expected_size) const;
  Eigen::Vector3d GetVector3(const std::string& key) const;

  const std::map<std::string, ParameterValue>& values() const { return values_; }
  bool operator==(const ParameterMap& other) const { return values_ == other.values_; }
  bool operator!=(const ParameterMap& other) const { return !(*this == other); }

 private:
  std::map<std::string, ParameterValue> values_;
};

}  // namespace unimap
