#pragma once
// Shared builders for the pose graph tests: a known 3D loop trajectory and a
// graph of noisy odometry plus exact loop closures over it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "graph/PoseGraph.hpp"

namespace unimap::graph::test {

// T = [AngleAxis(rotation_vector) | p].
inline Eigen::Isometry3d Exp(const Eigen::Vector3d& p, const Eigen::Vector3d& rotation_vector) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const double angle = rotation_vector.norm();
  if (angle > 0.0) T.linear() = Eigen::AngleAxisd(angle, rotation_vector / angle).toRotationMatrix();
  T.translation() = p;
  return T;
}

// n poses on a circle of radius 8 m, heading along the tangent, with a
// height wave (+-0.5 m) and small roll / pitch oscillations.
inline std::vector<Eigen::Isometry3d> CircleTruth(int n) {
  std::vector<Eigen::Isometry3d> truth;
  const double two_pi = 2.0 * std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    const double a = two_pi * i / n;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(8.0 * std::cos(a), 8.0 * std::sin(a), 0.5 * std::sin(2.0 * a));
    T.linear() = (Eigen::AngleAxisd(a + 0.25 * two_pi, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(0.05 * std::sin(3.0 * a), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(0.05 * std::cos(2.0 * a), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    truth.push_back(T);
  }
  return truth;
}

constexpr double kOdometrySigmaPosition_m = 0.05;
constexpr double kOdometrySigmaRotation_rad = 0.01;
constexpr double kLoopSigmaPosition_m = 0.02;
constexpr double kLoopSigmaRotation_rad = 0.005;

inline Matrix6d DiagonalSqrtInformation(double sigma_position_m, double sigma_rotation_rad) {
  Eigen::Matrix<double, 6, 1> d;
  d << Eigen::Vector3d::Constant(1.0 / sigma_position_m), Eigen::Vector3d::Constant(1.0 / sigma_rotation_rad);
  return d.asDiagonal();
}

// Exact loop closures back to the start (seen from across the circle):
// i -> 0 for every fourth node and for the last one.
inline std::vector<PoseConstraint> ExactLoopClosures(const std::vector<Eigen::Isometry3d>& truth) {
  const int n = static_cast<int>(truth.size());
  std::vector<std::pair<int, int>> pairs;
  for (int i = 4; i < n - 1; i += 4) pairs.emplace_back(i, 0);
  pairs.emplace_back(n - 1, 0);
  std::vector<PoseConstraint> out;
  for (const auto& [from, to] : pairs) {
    PoseConstraint c;
    c.from_node = from;
    c.to_node = to;
    c.T_from_to = truth[static_cast<std::size_t>(from)].inverse() * truth[static_cast<std::size_t>(to)];
    c.sqrt_information = DiagonalSqrtInformation(kLoopSigmaPosition_m, kLoopSigmaRotation_rad);
    c.kind = ConstraintKind::kLoopClosure;
    out.push_back(c);
  }
  return out;
}

// Odometry i -> i+1 (truth, times Exp(noise) when odometry_noise), initial
// poses by dead reckoning from truth[0], plus ExactLoopClosures.
inline PoseGraph NoisyLoopGraph(const std::vector<Eigen::Isometry3d>& truth, bool odometry_noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  PoseGraph graph;
  Eigen::Isometry3d T_world_node = truth.front();
  graph.AddNode(T_world_node);
  for (std::size_t i = 0; i + 1 < truth.size(); ++i) {
    PoseConstraint c;
    c.from_node = static_cast<int>(i);
    c.to_node = static_cast<int>(i + 1);
    c.T_from_to = truth[i].inverse() * truth[i + 1];
    if (odometry_noise) {
      const Eigen::Vector3d dp(n(rng), n(rng), n(rng));
      const Eigen::Vector3d dr(n(rng), n(rng), n(rng));
      c.T_from_to = c.T_from_to * Exp(kOdometrySigmaPosition_m * dp, kOdometrySigmaRotation_rad * dr);
    }
    c.sqrt_information = DiagonalSqrtInformation(kOdometrySigmaPosition_m, kOdometrySigmaRotation_rad);
    c.kind = ConstraintKind::kOdometry;
    T_world_node = T_world_node * c.T_from_to;
    graph.AddNode(T_world_node);
    graph.AddConstraint(c);
  }
  for (const PoseConstraint& c : ExactLoopClosures(truth)) graph.AddConstraint(c);
  return graph;
}

inline double MaxPositionError(const PoseGraph& graph, const std::vector<Eigen::Isometry3d>& truth) {
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    worst = std::max(worst, (graph.Pose(static_cast<int>(i)).translation() - truth[i].translation()).norm());
  }
  return worst;
}

inline double MaxRotationError(const PoseGraph& graph, const std::vector<Eigen::Isometry3d>& truth) {
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Matrix3d R = graph.Pose(static_cast<int>(i)).linear().transpose() * truth[i].linear();
    worst = std::max(worst, Eigen::AngleAxisd(R).angle());
  }
  return worst;
}

}  // namespace unimap::graph::test
