#include "graph/RelativePoseCost.hpp"

#include <ceres/autodiff_cost_function.h>

namespace unimap::graph {

RelativePoseCost::RelativePoseCost(const Eigen::Isometry3d& T_a_b_measured,
                                   const Eigen::Matrix<double, 6, 6>& sqrt_information)
    : p_ab_measured_(T_a_b_measured.translation()),
      q_ab_measured_inverse_(Eigen::Quaterniond(T_a_b_measured.rotation()).normalized().conjugate()),
      sqrt_information_(sqrt_information) {}

ceres::CostFunction* RelativePoseCost::Create(const Eigen::Isometry3d& T_a_b_measured,
                                              const Eigen::Matrix<double, 6, 6>& sqrt_information) {
  return new ceres::AutoDiffCostFunction<RelativePoseCost, 6, 3, 4, 3, 4>(
      new RelativePoseCost(T_a_b_measured, sqrt_information));
}

}  // namespace unimap::graph
