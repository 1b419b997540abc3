#include "graph/PoseGraph.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "PoseGraphFixtures.hpp"

namespace unimap::graph {
namespace {

using test::CircleTruth;
using test::Exp;
using test::MaxPositionError;
using test::MaxRotationError;
using test::NoisyLoopGraph;

TEST(SqrtInformationFromCovariance, RoundTripsTheInformation) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    Matrix6d A;
    for (int i = 0; i < 36; ++i) A(i) = n(rng);
    const Matrix6d covariance = 0.01 * (A * A.transpose() + 0.1 * Matrix6d::Identity());
    const Matrix6d S = SqrtInformationFromCovariance(covariance);
    const Matrix6d information = covariance.inverse();
    EXPECT_LT((S.transpose() * S - information).norm() / information.norm(), 1e-10) << trial;
    EXPECT_LT(S.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().maxCoeff(), 1e-300);
    EXPECT_GT(S.diagonal().minCoeff(), 0.0);
  }
  // Diagonal: S = diag(1 / sigma).
  Eigen::Matrix<double, 6, 1> sigma;
  sigma << 0.1, 0.2, 0.3, 0.01, 0.02, 0.03;
  const Matrix6d S = SqrtInformationFromCovariance(sigma.cwiseAbs2().asDiagonal());
  EXPECT_LT((S - Matrix6d(sigma.cwiseInverse().asDiagonal())).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SqrtInformationFromCovariance, RejectsBadCovariances) {
  Matrix6d indefinite = Matrix6d::Identity();
  indefinite(2, 2) = -1.0;
  EXPECT_THROW(SqrtInformationFromCovariance(indefinite), std::invalid_argument);
  EXPECT_THROW(SqrtInformationFromCovariance(Matrix6d::Zero()), std::invalid_argument);
  Matrix6d asymmetric = Matrix6d::Identity();
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(SqrtInformationFromCovariance(asymmetric), std::invalid_argument);
  Matrix6d nan = Matrix6d::Identity();
  nan(3, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SqrtInformationFromCovariance(nan), std::invalid_argument);
}

TEST(PoseGraphOptions, DefaultsAreValidAndRangesChecked) {
  std::string why;
  EXPECT_TRUE(PoseGraphOptions{}.IsValid(&why)) << why;
  PoseGraphOptions o;
  o.max_iterations = 0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_FALSE(why.empty());
  o = PoseGraphOptions{};
  o.threads = 0;
  EXPECT_FALSE(o.IsValid(nullptr));
  o = PoseGraphOptions{};
  o.max_solver_time_s = 0.0;
  EXPECT_FALSE(o.IsValid(nullptr));
  o = PoseGraphOptions{};
  o.loop_closure_huber_scale = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(o.IsValid(nullptr));
  o = PoseGraphOptions{};
  o.loop_closure_huber_scale = 0.0;  // no robust loss: valid
  EXPECT_TRUE(o.IsValid(nullptr));
}

TEST(PoseGraph, NodesAndInvalidInputs) {
  PoseGraph graph;
  EXPECT_EQ(graph.AddNode(Eigen::Isometry3d::Identity()), 0);
  EXPECT_EQ(graph.AddNode(Exp({1.0, 0.0, 0.0}, {0.0, 0.0, 0.5})), 1);
  EXPECT_EQ(graph.NodeCount(), 2u);
  EXPECT_LT((graph.Pose(1).matrix() - Exp({1.0, 0.0, 0.0}, {0.0, 0.0, 0.5}).matrix()).norm(), 1e-15);

  PoseConstraint c;
  c.from_node = 0;
  c.to_node = 1;
  EXPECT_NO_THROW(graph.AddConstraint(c));
  EXPECT_EQ(graph.ConstraintCount(), 1u);
  PoseConstraint bad = c;
  bad.to_node = 2;
  EXPECT_THROW(graph.AddConstraint(bad), std::invalid_argument);
  bad = c;
  bad.from_node = -1;
  EXPECT_THROW(graph.AddConstraint(bad), std::invalid_argument);
  bad = c;
  bad.to_node = 0;
  EXPECT_THROW(graph.AddConstraint(bad), std::invalid_argument);
  bad = c;
  bad.T_from_to.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(graph.AddConstraint(bad), std::invalid_argument);
  bad = c;
  bad.sqrt_information(4, 5) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(graph.AddConstraint(bad), std::invalid_argument);
  EXPECT_EQ(graph.ConstraintCount(), 1u);

  Eigen::Isometry3d nan_pose = Eigen::Isometry3d::Identity();
  nan_pose.translation().z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(graph.AddNode(nan_pose), std::invalid_argument);
  EXPECT_THROW(graph.SetPose(1, nan_pose), std::invalid_argument);
  EXPECT_THROW(graph.SetPose(2, Eigen::Isometry3d::Identity()), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(graph.Pose(-1)), std::invalid_argument);
  EXPECT_EQ(graph.NodeCount(), 2u);
}

TEST(PoseGraph, ConsistentGraphStaysPut) {
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(24);
  PoseGraph graph = NoisyLoopGraph(truth, /*odometry_noise=*/false, /*seed=*/1);
  // Start at the truth.
  for (std::size_t i = 0; i < truth.size(); ++i) graph.SetPose(static_cast<int>(i), truth[i]);
  const OptimizationSummary s = graph.Optimize(PoseGraphOptions{});
  ASSERT_TRUE(s.ok) << s.reason;
  EXPECT_LT(s.initial_cost, 1e-18);
  EXPECT_LT(s.final_cost, 1e-18);
  EXPECT_LT(MaxPositionError(graph, truth), 1e-9);
  EXPECT_LT(MaxRotationError(graph, truth), 1e-9);
  EXPECT_EQ(s.nodes, truth.size());
  EXPECT_EQ(s.constraints, graph.ConstraintCount());
}

TEST(PoseGraph, LoopClosuresRemoveOdometryDrift) {
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(36);
  PoseGraph graph = NoisyLoopGraph(truth, /*odometry_noise=*/true, /*seed=*/42);
  const PoseGraph before = graph;  // a copy: value semantics
  const double position_before = MaxPositionError(graph, truth);
  const double rotation_before = MaxRotationError(graph, truth);
  const Eigen::Matrix4d node0_before = graph.Pose(0).matrix();

  const OptimizationSummary s = graph.Optimize(PoseGraphOptions{});
  ASSERT_TRUE(s.ok) << s.reason;
  const double position_after = MaxPositionError(graph, truth);
  const double rotation_after = MaxRotationError(graph, truth);
  // Measured with seed 42: dead reckoning 1.613 m / 0.132 rad, optimised
  // 0.127 m / 0.0285 rad (seeds 1-3: 0.18-0.19 m, 0.034-0.041 rad). What
  // remains is the posterior uncertainty of the nodes up to two odometry
  // steps (sigma 0.05 m per axis each) from an anchored node, so the bounds
  // allow the other seeds' values, not just this one.
  EXPECT_GT(position_before, 1.0);
  EXPECT_LT(position_after, 0.2);
  EXPECT_LT(position_after, position_before / 8.0);
  EXPECT_LT(rotation_after, 0.045);
  EXPECT_LT(rotation_after, rotation_before / 3.0);
  EXPECT_LT(s.final_cost, s.initial_cost);
  EXPECT_GT(s.iterations, 0);
  // Node 0 is the anchor: bit for bit unchanged.
  EXPECT_TRUE(graph.Pose(0).matrix() == node0_before);
  // The copy taken before is untouched.
  EXPECT_DOUBLE_EQ(MaxPositionError(before, truth), position_before);
  std::printf("drift: position %.4f -> %.4f m, rotation %.5f -> %.5f rad, cost %.3g -> %.3g, %d iterations\n",
              position_before, position_after, rotation_before, rotation_after, s.initial_cost, s.final_cost,
              s.iterations);
}

// The cost is flat at a conflicted minimum: with cost ~25 and curvature
// ~100 per m^2, double precision resolves the minimiser only to about
// sqrt(eps * 25 / 100) ~ 1e-8 (measured errors 2e-9 to 4e-8); the
// hypotheses compared below differ by 0.1 or more.
constexpr double kConflictTolerance = 1e-7;

// Two nodes, two conflicting measurements of node 1 (x = 1 and x = 2, sqrt
// information 10 I): least squares lands at the mean 1.5. With a Huber loss
// of scale a on the second, 0.5 (10 (x-1))^2 + 0.5 rho((10 (2-x))^2) with
// rho(s) = 2 a sqrt(s) - a^2 is stationary at 100 (x-1) = 10 a: x = 1 + a/10.
double ConflictSolution(ConstraintKind second_kind, double huber_scale) {
  PoseGraph graph;
  graph.AddNode(Eigen::Isometry3d::Identity());
  graph.AddNode(Exp({0.3, 0.2, -0.1}, {0.0, 0.0, 0.1}));
  PoseConstraint first;
  first.from_node = 0;
  first.to_node = 1;
  first.T_from_to = Exp({1.0, 0.0, 0.0}, Eigen::Vector3d::Zero());
  first.sqrt_information = 10.0 * Matrix6d::Identity();
  PoseConstraint second = first;
  second.T_from_to = Exp({2.0, 0.0, 0.0}, Eigen::Vector3d::Zero());
  second.kind = second_kind;
  graph.AddConstraint(first);
  graph.AddConstraint(second);
  PoseGraphOptions options;
  options.loop_closure_huber_scale = huber_scale;
  options.max_iterations = 100;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  const OptimizationSummary s = graph.Optimize(options);
  EXPECT_TRUE(s.ok) << s.reason;
  EXPECT_LT(graph.Pose(1).translation().tail<2>().norm(), kConflictTolerance);
  EXPECT_LT(Eigen::AngleAxisd(graph.Pose(1).linear()).angle(), kConflictTolerance);
  return graph.Pose(1).translation().x();
}

TEST(PoseGraph, HuberLossOnLoopClosuresOnly) {
  EXPECT_NEAR(ConflictSolution(ConstraintKind::kLoopClosure, 1.0), 1.1, kConflictTolerance);
  EXPECT_NEAR(ConflictSolution(ConstraintKind::kLoopClosure, 2.0), 1.2, kConflictTolerance);
  EXPECT_NEAR(ConflictSolution(ConstraintKind::kLoopClosure, 0.0), 1.5, kConflictTolerance);  // disabled
  EXPECT_NEAR(ConflictSolution(ConstraintKind::kOdometry, 1.0), 1.5, kConflictTolerance);
  EXPECT_NEAR(ConflictSolution(ConstraintKind::kScanInSubmap, 1.0), 1.5, kConflictTolerance);
}

double MaxPositionDifference(const PoseGraph& a, const PoseGraph& b) {
  double worst = 0.0;
  for (int i = 0; i < static_cast<int>(a.NodeCount()); ++i) {
    worst = std::max(worst, (a.Pose(i).translation() - b.Pose(i).translation()).norm());
  }
  return worst;
}

TEST(PoseGraph, WrongLoopClosureDistortsLessUnderHuber) {
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(36);
  PoseGraph clean = NoisyLoopGraph(truth, /*odometry_noise=*/true, /*seed=*/42);
  PoseGraph robust = clean;
  // A false match between nodes 5 and 23 (say, the wrong bay of a
  // repetitive corridor): 6.3 m and 0.5 rad off.
  PoseConstraint wrong;
  wrong.from_node = 5;
  wrong.to_node = 23;
  wrong.T_from_to = truth[5].inverse() * truth[23] * Exp({6.0, -2.0, 0.3}, {0.0, 0.1, 0.5});
  wrong.sqrt_information = test::DiagonalSqrtInformation(test::kLoopSigmaPosition_m, test::kLoopSigmaRotation_rad);
  wrong.kind = ConstraintKind::kLoopClosure;
  robust.AddConstraint(wrong);
  PoseGraph least_squares = robust;

  PoseGraphOptions options;     // default Huber scale 1
  options.max_iterations = 50;  // the robust solve takes 14-20 steps here
  PoseGraphOptions plain = options;
  plain.loop_closure_huber_scale = 0.0;
  ASSERT_TRUE(clean.Optimize(options).ok);
  const OptimizationSummary s = robust.Optimize(options);
  ASSERT_TRUE(s.ok) << s.reason;
  EXPECT_EQ(s.reason.rfind("CONVERGENCE", 0), 0u) << s.reason;
  ASSERT_TRUE(least_squares.Optimize(plain).ok);
  const double robust_distortion = MaxPositionDifference(robust, clean);
  const double plain_distortion = MaxPositionDifference(least_squares, clean);
  std::printf("wrong loop closure moves the optimum by %.3f m under Huber, %.3f m without\n", robust_distortion,
              plain_distortion);
  // Measured (seeds 42, 1, 2): Huber 0.39 m, least squares 1.75-1.81 m. The
  // Huber pull is capped at a whitened force of a = 1 (50 N/m-equivalent at
  // sigma 0.02 m) whatever the offset, so its distortion stays near 0.4 m
  // (0.31 m at a 3 m offset, 0.40 m at 10 m) while least squares grows with
  // the offset (0.76 / 1.75 / 3.24 m at 3 / 6.3 / 10 m).
  EXPECT_LT(robust_distortion, 0.5);
  EXPECT_GT(plain_distortion, 1.5);
  EXPECT_LT(robust_distortion, plain_distortion / 3.0);
}

TEST(PoseGraph, InvalidOptionsAndEmptyGraphs) {
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(12);
  PoseGraph graph = NoisyLoopGraph(truth, /*odometry_noise=*/true, /*seed=*/3);
  const PoseGraph before = graph;
  PoseGraphOptions bad;
  bad.max_iterations = 0;
  const OptimizationSummary s = graph.Optimize(bad);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.reason.find("invalid options"), std::string::npos) << s.reason;
  for (int i = 0; i < 12; ++i) EXPECT_TRUE(graph.Pose(i).matrix() == before.Pose(i).matrix());

  PoseGraph empty;
  EXPECT_TRUE(empty.Optimize(PoseGraphOptions{}).ok);
  // Nodes without constraints are a no-op too, and keep their poses.
  empty.AddNode(Exp({1.0, 2.0, 3.0}, {0.1, 0.2, 0.3}));
  empty.AddNode(Exp({4.0, 5.0, 6.0}, {0.3, 0.2, 0.1}));
  const OptimizationSummary e = empty.Optimize(PoseGraphOptions{});
  EXPECT_TRUE(e.ok);
  EXPECT_EQ(e.nodes, 2u);
  EXPECT_EQ(e.constraints, 0u);
  EXPECT_LT((empty.Pose(1).translation() - Eigen::Vector3d(4.0, 5.0, 6.0)).norm(), 1e-15);
}

}  // namespace
}  // namespace unimap::graph
