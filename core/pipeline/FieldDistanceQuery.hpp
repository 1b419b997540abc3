#pragma once
#include <memory>
#include <optional>

#include "map/DistanceField.hpp"
#include "map/NeighborhoodPlane.hpp"
#include "matching/DistanceQuery.hpp"

namespace unimap::pipeline {

// The GPF's view of a distance-map snapshot (keeps the snapshot alive):
// trilinear between voxel centres (smooth below the voxel size, so particles
// closer than a voxel are told apart) or the containing voxel's value.
// Planes come from the field's cell planes or, given neighbourhood options,
// from a plane fitted to the surface cells around each point
// (FitNeighborhoodPlane; only kPlanar neighbourhoods give one).
class FieldDistanceQuery final : public matching::DistanceQuery {
 public:
  FieldDistanceQuery(std::shared_ptr<const map::DistanceField> field, bool trilinear,
                     std::optional<map::NeighborhoodPlaneOptions> neighborhood = std::nullopt)
      : field_(std::move(field)), trilinear_(trilinear), neighborhood_(neighborhood) {}
  void Distances(const Eigen::Vector3f* points_map, int n, float* out) const override {
    const map::DistanceField& field = *field_;
    if (trilinear_) {
      field.DistancesTrilinear(points_map, n, out);
    } else {
      for (int i = 0; i < n; ++i) out[i] = field.Distance(points_map[i]);
    }
  }
  void Planes(const Eigen::Vector3f* points_map, int n, bool* out, Eigen::Vector3f* normals,
              float* offsets_m) const override {
    const map::DistanceField& field = *field_;
    if (!neighborhood_) {
      for (int i = 0; i < n; ++i) out[i] = field.PlaneAt(points_map[i], &normals[i], &offsets_m[i]);
      return;
    }
    for (int i = 0; i < n; ++i) {
      const map::NeighborhoodPlane plane = map::FitNeighborhoodPlane(field, points_map[i], *neighborhood_);
      out[i] = plane.shape == map::NeighborhoodShape::kPlanar;
      normals[i] = plane.normal_map;
      offsets_m[i] = plane.offset_m;
    }
  }
  // Trilinear distances with their analytic gradients (whatever trilinear_ says).
  void DistancesAndGradients(const Eigen::Vector3f* points_map, int n, float* out,
                             Eigen::Vector3f* gradients_map) const override {
    const map::DistanceField& field = *field_;
    for (int i = 0; i < n; ++i) out[i] = field.DistanceTrilinear(points_map[i], &gradients_map[i]);
  }

 private:
  std::shared_ptr<const map::DistanceField> field_;
  bool trilinear_;
  std::optional<map::NeighborhoodPlaneOptions> neighborhood_;
};

}  // namespace unimap::pipeline
