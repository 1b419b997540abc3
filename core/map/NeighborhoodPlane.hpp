#pragma once
#include <string>

#include <Eigen/Core>

#include "map/DistanceField.hpp"

namespace unimap::map {

// Settings of FitNeighborhoodPlane.
struct NeighborhoodPlaneOptions {
  int radius_cells = 3;              // the neighbourhood: cells within this many cells per axis of the point's
  int min_cells = 6;                 // fewer surface cells than this: kTooFew
  double max_thickness_ratio = 0.1;  // planar when the smallest covariance eigenvalue is at most this
                                     // times the middle one
  double min_spread_ratio = 0.2;     // linear (one scan stripe) when the middle eigenvalue is below this
                                     // times the largest one

  bool IsValid(std::string* why) const;
};

// What the surface cells around a point look like.
enum class NeighborhoodShape {
  kTooFew,      // fewer than min_cells surface cells
  kLinear,      // they spread along one direction only (a single stripe a line scanner left)
  kPlanar,      // a plane: normal and offset are set
  kVolumetric,  // neither (an edge, a corner, a small object)
};

// The local surface around a point.
struct NeighborhoodPlane {
  NeighborhoodShape shape = NeighborhoodShape::kTooFew;
  Eigen::Vector3f normal_map = Eigen::Vector3f::UnitZ();  // unit normal (kPlanar)
  float offset_m = 0.0f;  // normal . x + offset is the signed height of x above the plane (kPlanar)
};

// Fits a plane to the centres of the surface cells (stored distance at most
// half a cell: the occupied voxels of a voxel-centre field) in the cube of
// radius_cells around the cell holding p_map, by principal components
// (eigenvalues l0 <= l1 <= l2 of their covariance): kPlanar when
// l0 <= max_thickness_ratio l1 and l1 >= min_spread_ratio l2, the normal
// being l0's eigenvector through their centroid. A line scanner leaves
// stripes; a plane through several of them is the surface itself, so a
// point beside a stripe can be measured across the surface instead of
// towards the stripe (docs/mapping.md, known limitation).
NeighborhoodPlane FitNeighborhoodPlane(const DistanceField& field, const Eigen::Vector3f& p_map,
                                       const NeighborhoodPlaneOptions& options);

}  // namespace unimap::map
