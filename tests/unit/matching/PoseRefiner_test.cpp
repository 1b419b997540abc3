#include "matching/PoseRefiner.hpp"

#include <gtest/gtest.h>

#include "AnalyticFields.hpp"
#include "estimation/So3.hpp"
#include "matching/GaussianParticleFilter.hpp"

namespace unimap::matching {
namespace {

const std::vector<int> kAllDims = {0, 1, 2, 3, 4, 5};

// Body points of the walls of a 10 x 6 x 4 m room seen from T_true.
std::vector<Eigen::Vector3f> RoomScan(const testing::BoxRoomField& room, const Eigen::Isometry3d& T_true) {
  std::vector<Eigen::Vector3f> out;
  const Eigen::Isometry3f T_body_map = T_true.inverse().cast<float>();
  for (const auto& p : room.SampleWalls(400, 7)) out.push_back(T_body_map * p);
  return out;
}

// The prediction is T_true with the error undone: T_true = T_predicted (+) error.
Eigen::Isometry3d Predicted(const Eigen::Isometry3d& T_true, const Vector6d& error) {
  Eigen::Isometry3d T = T_true;
  T.translation() -= error.head<3>();
  T.linear() = T_true.linear() * estimation::ExpQ(-error.tail<3>()).toRotationMatrix();
  return T;
}

Eigen::Isometry3d TrueRoomPose() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.7, -0.4, 0.2);
  T.linear() = estimation::ExpQ(Eigen::Vector3d(0.02, -0.03, 0.4)).toRotationMatrix();
  return T;
}

TEST(DistanceQuery, DefaultGradientsDifferentiateTheDistances) {
  // Outside the sphere the gradient of |p| - r is p / |p|.
  const testing::SphereField sphere(1.0f);
  const Eigen::Vector3f points[2] = {Eigen::Vector3f(1.5f, 0.5f, -0.3f), Eigen::Vector3f(-0.2f, 2.0f, 0.7f)};
  float d[2];
  Eigen::Vector3f g[2];
  sphere.DistancesAndGradients(points, 2, d, g);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(d[i], points[i].norm() - 1.0f, 1e-6f);
    EXPECT_LT((g[i] - points[i].normalized()).norm(), 1e-3f) << i;
  }
}

TEST(PoseRefiner, RecoversAKnownOffsetInARoom) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const Eigen::Isometry3d T_true = TrueRoomPose();
  Vector6d error;
  error << 0.06, -0.05, 0.04, 0.01, -0.015, 0.02;
  const std::vector<Eigen::Vector3f> points = RoomScan(room, T_true);
  // A broad prior and a sharp likelihood: the MAP is the true pose to well
  // below a millimetre (the prior pulls by ~ H^-1 P^-1 e, about 1e-6 m here).
  const Matrix6d prior = Matrix6d::Identity();
  const PoseRefiner refiner(0.05, 0.5, 400.0, 20);
  const PoseRefinement r =
      refiner.Refine(Predicted(T_true, error), Vector6d::Zero(), prior, Vector6d::Zero(), kAllDims, points, room);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_GE(r.iterations, 2);
  EXPECT_LT((r.mean.head<3>() - error.head<3>()).norm(), 5e-4);
  EXPECT_LT((r.mean.tail<3>() - error.tail<3>()).norm(), 2e-4);
  EXPECT_LE(r.final_cost, r.initial_cost);
  // The posterior is the Laplace one: (P^-1 + H)^-1.
  const Matrix6d expected = (prior.inverse() + r.information).inverse();
  EXPECT_LT((r.covariance - expected).norm(), 1e-9 * expected.norm() + 1e-15);
}

TEST(PoseRefiner, InformationOfAPlaneIsExact) {
  // Points on the floor z = 0 seen from a level body at height 0: each has
  // gradient (0, 0, 1) and rotation row p x (0, 0, 1) = (y, -x, 0), so with
  // W = E / (n sigma^2): H_zz = E / sigma^2, H_{z,roll} = W sum y,
  // H_{roll,roll} = W sum y^2, and nothing on x, y or yaw.
  const testing::FloorField floor;
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 4; ++j) points.emplace_back(static_cast<float>(i) - 2.0f, 0.5f * static_cast<float>(j), 0.0f);
  }
  const double sigma = 0.1, effective = 20.0;
  const double W = effective / (static_cast<double>(points.size()) * sigma * sigma);
  double sum_x = 0.0, sum_y = 0.0, sum_yy = 0.0, sum_xx = 0.0, sum_xy = 0.0;
  for (const auto& p : points) {
    sum_x += p.x();
    sum_y += p.y();
    sum_xx += p.x() * p.x();
    sum_yy += p.y() * p.y();
    sum_xy += p.x() * p.y();
  }
  const PoseRefiner refiner(sigma, 0.5, effective, 5);
  const Matrix6d prior = Matrix6d::Identity() * 1e-4;
  const PoseRefinement r =
      refiner.Refine(Eigen::Isometry3d::Identity(), Vector6d::Zero(), prior, Vector6d::Zero(), kAllDims, points, floor);
  ASSERT_TRUE(r.ok) << r.reason;
  const Matrix6d& H = r.information;
  EXPECT_NEAR(H(2, 2), effective / (sigma * sigma), 1e-9);
  EXPECT_NEAR(H(2, 3), W * sum_y, 1e-9);
  EXPECT_NEAR(H(2, 4), -W * sum_x, 1e-9);
  EXPECT_NEAR(H(3, 3), W * sum_yy, 1e-9);
  EXPECT_NEAR(H(4, 4), W * sum_xx, 1e-9);
  EXPECT_NEAR(H(3, 4), -W * sum_xy, 1e-9);
  for (int i : {0, 1, 5}) EXPECT_EQ(H.row(i).norm(), 0.0) << i;
  // Already at the optimum: nothing moves.
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.mean, Vector6d::Zero());
}

TEST(PoseRefiner, PlanePointsRecoverAnOffsetWithNumericallyCheckedInformation) {
  // Points on three tilted planes through the true pose's surroundings,
  // tied to their planes; the prediction is off by a known error.
  const Eigen::Isometry3d T_true = TrueRoomPose();
  Vector6d error;
  error << 0.04, -0.03, 0.05, 0.01, -0.02, 0.015;
  const Eigen::Vector3f normals[3] = {Eigen::Vector3f(0.1f, 0.0f, 1.0f).normalized(),
                                      Eigen::Vector3f(1.0f, 0.2f, 0.0f).normalized(),
                                      Eigen::Vector3f(-0.1f, 1.0f, 0.2f).normalized()};
  const float offsets[3] = {1.2f, -2.5f, 1.8f};
  std::vector<PlanePoint> points;
  const Eigen::Isometry3f T_body_map = T_true.inverse().cast<float>();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3f u = normals[k].unitOrthogonal();
    const Eigen::Vector3f v = normals[k].cross(u);
    for (int i = 0; i < 40; ++i) {
      const Eigen::Vector3f p_map = -offsets[k] * normals[k] + 0.1f * static_cast<float>(i % 8 - 4) * 3.0f * u +
                                    0.5f * static_cast<float>(i / 8 - 2) * v;
      points.push_back({T_body_map * p_map, normals[k], offsets[k]});
    }
  }
  const testing::FloorField unused;  // no field points
  const double sigma = 0.1, effective = 50.0;
  const PoseRefiner refiner(sigma, 0.5, effective, 20);
  const Eigen::Isometry3d T_predicted = Predicted(T_true, error);
  const PoseRefinement r = refiner.Refine(T_predicted, Vector6d::Zero(), Matrix6d::Identity(), Vector6d::Zero(),
                                          kAllDims, {}, points, unused);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT((r.mean - error).norm(), 1e-4);
  // H = W sum J J' with J the residuals' derivatives by central differences,
  // the rotation's for a perturbation local to the estimate, R(e) Exp(delta)
  // (the refiner's convention, as for field points).
  const Eigen::Isometry3d T_mean = estimation::ApplyPoseError(T_predicted, r.mean);
  const double W = effective / (static_cast<double>(points.size()) * sigma * sigma);
  Matrix6d H = Matrix6d::Zero();
  for (const PlanePoint& q : points) {
    Vector6d J;
    for (int a = 0; a < 6; ++a) {
      Vector6d step = Vector6d::Zero();
      step(a) = 1e-5;
      const auto residual = [&](const Vector6d& e) {
        const Eigen::Vector3d p = estimation::ApplyPoseError(T_mean, e) * q.p_body.cast<double>();
        return q.normal_map.cast<double>().dot(p) + q.offset_m;
      };
      J(a) = (residual(step) - residual(-step)) / 2e-5;
    }
    H += W * J * J.transpose();
  }
  EXPECT_LT((r.information - H).norm(), 1e-3 * H.norm()) << r.information << "\n\n" << H;
}

TEST(PoseRefiner, UnobservedDirectionsStayWithThePrior) {
  // A body 3 cm above the floor and 2 cm off in x: z is corrected to the
  // MAP of prior and likelihood, x (no gradient) returns to the prior mean.
  const testing::FloorField floor;
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 30; ++i)
    points.emplace_back(0.3f * static_cast<float>(i % 6) - 0.75f, 0.2f * static_cast<float>(i / 6) - 0.4f, -0.03f);
  const double sigma = 0.1, effective = 20.0;
  const double prior_var = 0.01 * 0.01;
  Vector6d start = Vector6d::Zero();
  start(0) = 0.02;
  const PoseRefiner refiner(sigma, 0.5, effective, 10);
  const PoseRefinement r = refiner.Refine(Eigen::Isometry3d::Identity(), Vector6d::Zero(),
                                          Matrix6d::Identity() * prior_var, start, kAllDims, points, floor);
  ASSERT_TRUE(r.ok) << r.reason;
  // z: minimise dz^2 / (2 p) + (E / sigma^2) (dz - 0.03)^2 / 2 => dz = 0.03 h / (h + 1/p).
  const double h = effective / (sigma * sigma);
  EXPECT_NEAR(r.mean(2), 0.03 * h / (h + 1.0 / prior_var), 1e-6);
  EXPECT_NEAR(r.mean(0), 0.0, 1e-9);
  EXPECT_NEAR(r.covariance(0, 0), prior_var, 1e-12);
  EXPECT_NEAR(r.covariance(2, 2), 1.0 / (h + 1.0 / prior_var), 1e-9);
}

TEST(PoseRefiner, InactiveDimensionsAreLeftAlone) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const Eigen::Isometry3d T_true = TrueRoomPose();
  Vector6d error;
  error << 0.05, -0.04, 0.03, 0.0, 0.0, 0.02;
  const PoseRefiner refiner(0.05, 0.5, 400.0, 20);
  const PoseRefinement r = refiner.Refine(Predicted(T_true, error), Vector6d::Zero(), Matrix6d::Identity(),
                                          Vector6d::Zero(), {0, 1, 5}, RoomScan(room, T_true), room);
  ASSERT_TRUE(r.ok) << r.reason;
  for (int i : {2, 3, 4}) {
    EXPECT_EQ(r.mean(i), 0.0) << i;
    EXPECT_EQ(r.information.row(i).norm(), 0.0) << i;
    EXPECT_EQ(r.covariance(i, i), 1.0) << i;
  }
  EXPECT_LT(std::abs(r.mean(0) - 0.05), 0.01);
  EXPECT_LT(std::abs(r.mean(5) - 0.02), 0.005);
}

TEST(PoseRefiner, BadInputIsAResultNotACrash) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const PoseRefiner refiner(0.1, 0.5, 20.0, 5);
  const PoseRefinement empty = refiner.Refine(Eigen::Isometry3d::Identity(), Vector6d::Zero(), Matrix6d::Identity(),
                                              Vector6d::Zero(), kAllDims, {}, room);
  EXPECT_FALSE(empty.ok);
  EXPECT_EQ(empty.reason, "no points to match");
  const PoseRefinement singular = refiner.Refine(Eigen::Isometry3d::Identity(), Vector6d::Zero(), Matrix6d::Zero(),
                                                 Vector6d::Zero(), kAllDims, {Eigen::Vector3f(1.0f, 0.0f, 0.0f)}, room);
  EXPECT_FALSE(singular.ok);
  EXPECT_EQ(singular.reason, "prior covariance is not positive definite");
}

TEST(PoseRefiner, GpfWithRefinementIsDeterministicAndCloserThanParticlesAlone) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  const Eigen::Isometry3d T_true = TrueRoomPose();
  Vector6d error;
  error << 0.03, -0.02, 0.02, 0.004, -0.004, 0.008;
  const std::vector<Eigen::Vector3f> points = RoomScan(room, T_true);
  const Matrix6d prior = Matrix6d::Identity() * 0.03 * 0.03;
  GpfOptions options;
  options.effective_points = 200.0;
  options.point_sigma_m = 0.05;
  GaussianParticleFilter plain(options);
  options.refine_iterations = 10;
  GaussianParticleFilter refined_a(options), refined_b(options);
  const Eigen::Isometry3d T_predicted = Predicted(T_true, error);
  const GpfResult p = plain.Match(T_predicted, prior, points, room);
  const GpfResult a = refined_a.Match(T_predicted, prior, points, room);
  const GpfResult b = refined_b.Match(T_predicted, prior, points, room);
  ASSERT_TRUE(p.ok && a.ok && b.ok);
  EXPECT_FALSE(p.refined);
  EXPECT_TRUE(a.refined);
  EXPECT_EQ(a.posterior_mean, b.posterior_mean);
  EXPECT_LT((a.posterior_mean - error).norm(), (p.posterior_mean - error).norm());
  EXPECT_LT((a.posterior_mean.head<3>() - error.head<3>()).norm(), 3e-3);
  // The pseudo measurement reproduces the refined posterior in a Kalman update from N(0, prior).
  const Matrix6d K = prior * (prior + a.measurement.R).inverse();
  EXPECT_LT((K * a.measurement.z - a.posterior_mean).norm(), 1e-6);
}

}  // namespace
}  // namespace unimap::matching
