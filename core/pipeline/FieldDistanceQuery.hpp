#pragma once
#include <memory>
#include <optional>

#include "map/DistanceField.hpp"
#include "map/NeighbourhoodPlane.hpp"
#include "matching/DistanceQuery.hpp"

namespace unimap::pipeline {

// The GPF's view of a distance-map snapshot (keeps the snapshot alive):
// trilinear between voxel centres (smooth below the voxel size, so particles
// closer than a voxel are told apart) or the containing voxel's value.
// Planes come from the field's cell planes or, given neighbourhood options,
// from a plane fitted to the surface cells around each point
// (FitNeighbourhoodPlane; only kPlanar neighbourhoods give one).
class FieldDistanceQuery final : public matching::DistanceQuery {
 public:
  FieldDistanceQuery(std::shared_ptr<const map::DistanceField> field, bool trilinear,
                     std::optional<map::NeighbourhoodPlaneOptions> neighbourhood = std::nullopt)
      : field_(std::move(field)), trilinear_(trilinear), neighbourhood_(neighbourhood) {}
  void Distances(const Eigen::Vector3f* points_map, int n, float* out) const override {
    const map::DistanceField& field = *field_;
    if (trilinear_) {
      for (int i = 0; i < n; ++i) out[i] = field.DistanceTrilinear(points_map[i], nullptr);
    } else {
      for (int i = 0; i < n; ++i) out[i] = field.Distance(points_map[i]);
    }
  }
  void Planes(const Eigen::Vector3f* points_map, int n, bool* out, Eigen::Vector3f* normals,
              float* offsets_m) const override {
    const map::DistanceField& field = *field_;
    if (!neighbourhood_) {
      for (int i = 0; i < n; ++i) out[i] = field.PlaneAt(points_map[i], &normals[i], &offsets_m[i]);
      return;
    }
    for (int i = 0; i < n; ++i) {
      const map::NeighbourhoodPlane plane = map::FitNeighbourhoodPlane(field, points_map[i], *neighbourhood_);
      out[i] = plane.shape == map::NeighbourhoodShape::kPlanar;
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
  std::optional<map::NeighbourhoodPlaneOptions> neighbourhood_;
};

}  // namespace unimap::pipeline
