#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace unimap::graph {

// Relative pose residual between two graph nodes a (`from`) and b (`to`),
// after the idea of ceres examples/slam/pose_graph_3d. Parameter blocks,
// each a raw array: p_a (3), q_a (4, Eigen order x y z w), p_b (3), q_b (4),
// the poses T_world_a and T_world_b. With the estimated relative pose
//   q_ab = q_a^-1 q_b,   p_ab = q_a^-1 (p_b - p_a),
// the residual is
//   r = S [ p_ab - p_ab_meas ;  2 vec(q_ab_meas^-1 q_ab) ]
// where S is the square root of the information. The translation error is
// expressed in frame a; the rotation error is the right (frame b) error,
// q_ab = q_ab_meas Exp(dtheta) with 2 vec(.) = dtheta up to O(|dtheta|^3),
// i.e. the rotation vector for small errors.
class RelativePoseCost {
 public:
  // T_a_b_measured: measured pose of b in frame a; sqrt_information: 6x6,
  // order [translation xyz, rotation xyz].
  RelativePoseCost(const Eigen::Isometry3d& T_a_b_measured, const Eigen::Matrix<double, 6, 6>& sqrt_information);

  // Evaluates the residual above (6 values) for any scalar type (double or
  // ceres::Jet); always returns true.
  template <typename T>
  bool operator()(const T* p_a_raw, const T* q_a_raw, const T* p_b_raw, const T* q_b_raw, T* residual_raw) const {
    using Vector3T = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vector3T> p_a(p_a_raw);
    const Eigen::Map<const Eigen::Quaternion<T>> q_a(q_a_raw);
    const Eigen::Map<const Vector3T> p_b(p_b_raw);
    const Eigen::Map<const Eigen::Quaternion<T>> q_b(q_b_raw);

    const Eigen::Quaternion<T> q_a_inverse = q_a.conjugate();
    const Eigen::Quaternion<T> q_ab = q_a_inverse * q_b;
    const Vector3T p_ab = q_a_inverse * (p_b - p_a);
    const Eigen::Quaternion<T> q_error = q_ab_measured_inverse_.template cast<T>() * q_ab;

    Eigen::Matrix<T, 6, 1> error;
    error.template head<3>() = p_ab - p_ab_measured_.template cast<T>();
    error.template tail<3>() = T(2.0) * q_error.vec();
    Eigen::Map<Eigen::Matrix<T, 6, 1>> residual(residual_raw);
    residual = sqrt_information_.template cast<T>() * error;
    return true;
  }

  // A new autodiff cost function (6 residuals; blocks 3, 4, 3, 4) owning a
  // copy of this functor; the caller (normally ceres::Problem) owns it.
  static ceres::CostFunction* Create(const Eigen::Isometry3d& T_a_b_measured,
                                     const Eigen::Matrix<double, 6, 6>& sqrt_information);

 private:
  Eigen::Vector3d p_ab_measured_;
  Eigen::Quaterniond q_ab_measured_inverse_;  // unit
  Eigen::Matrix<double, 6, 6> sqrt_information_;
};

}  // namespace unimap::graph
