#pragma once
#include <memory>

#include "map/DistanceField.hpp"
#include "matching/DistanceQuery.hpp"

namespace unimap::pipeline {

// The GPF's view of a distance-map snapshot (keeps the snapshot alive).
class FieldDistanceQuery final : public matching::DistanceQuery {
 public:
  explicit FieldDistanceQuery(std::shared_ptr<const map::DistanceField> field) : field_(std::move(field)) {}
  void Distances(const Eigen::Vector3f* points_map, int n, float* out) const override {
    const map::DistanceField& field = *field_;
    for (int i = 0; i < n; ++i) out[i] = field.Distance(points_map[i]);
  }

 private:
  std::shared_ptr<const map::DistanceField> field_;
};

}  // namespace unimap::pipeline
