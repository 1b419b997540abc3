#pragma once
#include <string>

#include <Eigen/Geometry>

#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap {

// A rigid transform as written in platform files: translation (m) and
// roll/pitch/yaw (deg), R = Rz(yaw) * Ry(pitch) * Rx(roll).
struct UNIMAP_SDK_API Extrinsic {
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_deg = Eigen::Vector3d::Zero();

  // The transform T_a_b this extrinsic describes (maps b-frame points into a).
  Eigen::Isometry3d ToIsometry() const;
  // Adds "<prefix>.translation_m" and "<prefix>.rpy_deg" with these defaults.
  void AddTo(ParameterSet* set, const std::string& prefix, const std::string& what) const;
  // Reads the two keys under prefix; throws ConfigError.
  static Extrinsic FromMap(const ParameterMap& map, const std::string& prefix);
};

}  // namespace unimap
