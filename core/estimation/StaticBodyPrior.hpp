#pragma once
#include "estimation/MotionPrior.hpp"

namespace unimap::estimation {

// The body does not move (a scanner on a fixed stand or tripod: a tilting
// or rotating 2D LiDAR building one 3D scan of a room). Every prediction is
// the identity with no uncertainty; the localiser then places every scan at
// the start pose without matching it (MotionSource::kStatic), so what the
// map shows is the payload's geometry alone (its extrinsics and encoder).
class StaticBodyPrior final : public MotionPrior {
 public:
  void AddOdometry(const OdometrySample& /*sample*/) override {}
  bool ReadyFor(double /*time_s*/) const override { return true; }
  MotionPrediction Predict(double /*t0*/, double /*t1*/) const override {
    MotionPrediction prediction;
    prediction.ok = true;
    return prediction;
  }
  void Observe(double /*time_s*/, const Eigen::Isometry3d& /*T_world_body*/) override {}
};

}  // namespace unimap::estimation
