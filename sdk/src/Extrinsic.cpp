#include "unimap/Extrinsic.hpp"

#include <cmath>

namespace unimap {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

Eigen::Isometry3d Extrinsic::ToIsometry() const {
  const Eigen::Vector3d rpy_rad = rpy_deg * kDegToRad;
  // R = Rz(yaw) * Ry(pitch) * Rx(roll)
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(rpy_rad.z(), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(rpy_rad.y(), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(rpy_rad.x(), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = translation_m;
  return T;
}

void Extrinsic::AddTo(ParameterSet* set, const std::string& prefix, const std::string& what) const {
  set->Add({prefix + ".translation_m",
            "",
            what + ": translation x, y, z (m)",
            std::vector<double>{translation_m.x(), translation_m.y(), translation_m.z()},
            -100.0,
            100.0,
            {}});
  set->Add({prefix + ".rpy_deg",
            "",
            what + ": roll, pitch, yaw, R = Rz*Ry*Rx (deg)",
            std::vector<double>{rpy_deg.x(), rpy_deg.y(), rpy_deg.z()},
            -360.0,
            360.0,
            {}});
}

Extrinsic Extrinsic::FromMap(const ParameterMap& map, const std::string& prefix) {
  Extrinsic e;
  e.translation_m = map.GetVector3(prefix + ".translation_m");
  e.rpy_deg = map.GetVector3(prefix + ".rpy_deg");
  return e;
}

}  // namespace unimap
