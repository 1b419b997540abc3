#pragma once
// Least-squares rigid and similarity alignment of two point sets (Umeyama 1991).
#include <optional>
#include <vector>

#include <Eigen/Geometry>

namespace unimap::eval {

// The rigid transform that best maps source points onto target points.
struct RigidAlignment {
  Eigen::Isometry3d T_target_source = Eigen::Isometry3d::Identity();  // argmin sum |T s_i - t_i|^2
  double rmse_m = 0.0;                                                // sqrt(mean |T s_i - t_i|^2) at the optimum
};

// Umeyama's closed form without scale. Requires source.size() ==
// target.size() >= 1 (throws InputError otherwise). Degenerate sets (all
// points equal, collinear) give one of the equally good optima.
RigidAlignment AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target);

// The similarity transform that best maps source points onto target points.
struct SimilarityAlignment {
  Eigen::Isometry3d T_target_source = Eigen::Isometry3d::Identity();  // rotation R and translation t
  double scale = 1.0;                                                 // c: argmin sum |c R s_i + t - t_i|^2 (> 0)
  double rmse_m = 0.0;                                                // sqrt(mean |c R s_i + t - t_i|^2) at the optimum
};

// Umeyama's closed form with scale (eq. 42). Requires source.size() ==
// target.size() >= 1 (throws InputError otherwise); empty when no positive
// scale exists (the source points all coincide, or the target's do).
std::optional<SimilarityAlignment> AlignSimilarity(const std::vector<Eigen::Vector3d>& source,
                                                   const std::vector<Eigen::Vector3d>& target);

}  // namespace unimap::eval
