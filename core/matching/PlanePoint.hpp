#pragma once
#include <Eigen/Core>

namespace unimap::matching {

// A scan point tied to a surface plane of the map (point to plane, as in
// ICP): at a pose T_map_body its signed distance is
//   normal_map . (T_map_body p_body) + offset_m.
// The tie is made once per scan, at the predicted pose, to the plane of the
// surface nearest to the point there (DistanceQuery::Planes).
struct PlanePoint {
  Eigen::Vector3f p_body = Eigen::Vector3f::Zero();       // the point (body frame)
  Eigen::Vector3f normal_map = Eigen::Vector3f::UnitZ();  // unit plane normal (map frame)
  float offset_m = 0.0f;                                  // plane offset (m)

  // Signed distance from the plane of the point moved to p_map (= T_map_body p_body).
  float SignedDistance(const Eigen::Vector3f& p_map) const { return normal_map.dot(p_map) + offset_m; }
};

}  // namespace unimap::matching
