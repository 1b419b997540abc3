#include "matching/GaussianParticleFilter.hpp"

#include <gtest/gtest.h>

#include "AnalyticFields.hpp"
#include "estimation/So3.hpp"

namespace unimap::matching {
namespace {

struct Case {
  Eigen::Isometry3d T_true = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_predicted = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3f> points_body;
};

// A body in a 10 x 6 x 4 m room; the prediction is off by a known error.
Case MakeCase(const testing::BoxRoomField& room, const Vector6d& prediction_error) {
  Case c;
  c.T_true.translation() = Eigen::Vector3d(0.7, -0.4, 0.2);
  c.T_true.linear() = estimation::ExpQ(Eigen::Vector3d(0.02, -0.03, 0.4)).toRotationMatrix();
  c.T_predicted = c.T_true;
  c.T_predicted.translation() -= prediction_error.head<3>();
  c.T_predicted.linear() = c.T_true.linear() * estimation::ExpQ(-prediction_error.tail<3>()).toRotationMatrix();
  const Eigen::Isometry3f T_body_map = c.T_true.inverse().cast<float>();
  for (const auto& p : room.SampleWalls(3000, 4)) c.points_body.push_back(T_body_map * p);
  return c;
}

// Error of the predicted pose after applying a correction [dp, dtheta].
double PositionErrorAfter(const Case& c, const Vector6d& correction) {
  return (c.T_predicted.translation() + correction.head<3>() - c.T_true.translation()).norm();
}

TEST(GaussianParticleFilter, PosteriorMovesToTheTruePose) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  Vector6d error;
  error << 0.06, -0.05, 0.04, 0.01, -0.01, 0.02;
  const Case c = MakeCase(room, error);
  Matrix6d prior = Matrix6d::Zero();
  prior.diagonal() << 0.08, 0.08, 0.08, 0.02, 0.02, 0.02;
  prior = prior.array().square().matrix();
  GpfOptions options;
  options.num_particles = 1000;
  options.effective_points = 50.0;  // a sharp likelihood: one scan from a whole room
  GaussianParticleFilter gpf(options);
  const GpfResult r = gpf.Match(c.T_predicted, prior, c.points_body, room);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LE(r.points_used, options.max_points);
  // The prediction was 9 cm off; the posterior mean must be much closer.
  EXPECT_GT(PositionErrorAfter(c, Vector6d::Zero()), 0.085);
  EXPECT_LT(PositionErrorAfter(c, r.posterior_mean), 0.02);
  // Rotation error at least halved, and the truth consistent with the
  // posterior (Mahalanobis^2 below the 99.9 % chi-square bound, 6 dof).
  EXPECT_LT((r.posterior_mean.tail<3>() - error.tail<3>()).norm(), 0.5 * error.tail<3>().norm());
  const Vector6d miss = error - r.posterior_mean;
  EXPECT_LT(miss.dot(r.posterior_covariance.ldlt().solve(miss)), 22.46);
  // The posterior is tighter than the prior in every direction.
  for (int i = 0; i < 6; ++i) EXPECT_LT(r.posterior_covariance(i, i), r.sample_covariance(i, i)) << i;
  EXPECT_GT(r.effective_sample_size, 5.0);
}

TEST(GaussianParticleFilter, DeterministicForASeedAndThreadCount) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  Vector6d error;
  error << 0.03, 0.02, -0.01, 0.0, 0.01, -0.01;
  const Case c = MakeCase(room, error);
  const Matrix6d prior = Matrix6d::Identity() * 0.0025;
  GpfOptions options;
  GaussianParticleFilter a(options), b(options);
  options.threads = 2;
  GaussianParticleFilter parallel(options);
  const GpfResult ra = a.Match(c.T_predicted, prior, c.points_body, room);
  const GpfResult rb = b.Match(c.T_predicted, prior, c.points_body, room);
  const GpfResult rp = parallel.Match(c.T_predicted, prior, c.points_body, room);
  EXPECT_EQ(ra.posterior_mean, rb.posterior_mean);
  EXPECT_EQ(ra.posterior_covariance, rb.posterior_covariance);
  EXPECT_EQ(ra.posterior_mean, rp.posterior_mean);
  EXPECT_EQ(ra.measurement.z, rp.measurement.z);
}

TEST(GaussianParticleFilter, PlanarModeLeavesOtherDimensionsAlone) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  Vector6d error;
  error << 0.05, -0.04, 0.0, 0.0, 0.0, 0.02;
  const Case c = MakeCase(room, error);
  Matrix6d prior = Matrix6d::Identity() * 0.0036;
  GpfOptions options;
  options.planar = true;
  options.effective_points = 50.0;  // a sharp likelihood: one scan from a whole room
  GaussianParticleFilter gpf(options);
  const GpfResult r = gpf.Match(c.T_predicted, prior, c.points_body, room);
  ASSERT_TRUE(r.ok) << r.reason;
  for (int i : {2, 3, 4}) EXPECT_EQ(r.posterior_mean(i), 0.0);
  // No information on z, roll, pitch: R there dwarfs the prior, so the
  // Kalman gain K = P / (P + R) is below 1e-3.
  for (int i : {2, 3, 4}) EXPECT_GT(r.measurement.R(i, i), 1e3 * prior(i, i)) << i;
  EXPECT_LT(std::abs(r.posterior_mean(0) - 0.05), 0.015);
  EXPECT_LT(std::abs(r.posterior_mean(5) - 0.02), 0.006);
}

// Posterior x of a scan taken at the true pose (identity, also the
// prediction) in a map that has seen only part of the floor
// (PartlySeenFloorField, or a query with the same distances).
double PosteriorXOnAPartlySeenFloor(const DistanceQuery& field, bool point_to_plane, bool planes_only,
                                    int refine_iterations, double max_predicted_distance_m = 0.0,
                                    int* points_unseen = nullptr) {
  Matrix6d prior = Matrix6d::Zero();
  prior.diagonal() << 0.05, 0.05, 0.05, 0.01, 0.01, 0.01;
  prior = prior.array().square().matrix();
  GpfOptions options;
  options.num_particles = 1000;
  options.effective_points = 50.0;
  options.refine_iterations = refine_iterations;
  options.point_to_plane = point_to_plane;
  options.planes_only = planes_only;
  GaussianParticleFilter gpf(options);
  const GpfResult r = gpf.Match(Eigen::Isometry3d::Identity(), prior, testing::PartlySeenFloorField::SampleScan(900, 3),
                                field, max_predicted_distance_m);
  EXPECT_TRUE(r.ok) << r.reason;
  if (points_unseen != nullptr) *points_unseen = r.points_unseen;
  return r.posterior_mean.x();
}

double PosteriorXOnAPartlySeenFloor(bool point_to_plane, int refine_iterations) {
  return PosteriorXOnAPartlySeenFloor(testing::PartlySeenFloorField(), point_to_plane, false, refine_iterations);
}

TEST(GaussianParticleFilter, PointToPlaneKeepsPointsOnAPartlySeenSurfaceFromPullingTowardsItsEdge) {
  // Floor points beyond the seen edge (x > 1) measured in the field are
  // closer to it the further the pose moves back (-x): the estimate slips
  // back although the scan was taken at the truth. Tied to the floor's plane
  // they say nothing about x; the wall x = -2 fixes x at the truth.
  for (const int refine : {0, 5}) {
    const double field_x = PosteriorXOnAPartlySeenFloor(false, refine);
    const double plane_x = PosteriorXOnAPartlySeenFloor(true, refine);
    EXPECT_LT(field_x, -0.01) << refine;
    EXPECT_LT(std::abs(plane_x), 0.003) << refine;
  }
}

TEST(GaussianParticleFilter, PointsFarFromTheMapAtThePredictionAreNotMeasured) {
  // The floor beyond the seen edge (x > 1) lies up to 2 m from what the map
  // holds; with max_predicted_distance_m those points are left out and the
  // estimate stays at the truth.
  const testing::PartlySeenFloorField field;
  for (const int refine : {0, 5}) {
    int unseen = -1;
    const double all_x = PosteriorXOnAPartlySeenFloor(field, false, false, refine, 0.0, &unseen);
    EXPECT_EQ(unseen, 0);
    const double gated_x = PosteriorXOnAPartlySeenFloor(field, false, false, refine, 0.15, &unseen);
    EXPECT_LT(all_x, -0.01) << refine;
    EXPECT_LT(std::abs(gated_x), 0.003) << refine;
    // About a third of the floor points (a ninth of the scan, before
    // downsampling to 300 points) lie beyond x = 1.15.
    EXPECT_GT(unseen, 15) << refine;
    EXPECT_LT(unseen, 60) << refine;
  }
}

TEST(GaussianParticleFilter, NoPointNearTheMapIsAResult) {
  const testing::PartlySeenFloorField field;
  GaussianParticleFilter gpf(GpfOptions{});
  // 1 m above the floor, 1.5 m and more from the walls.
  const GpfResult r = gpf.Match(Eigen::Isometry3d::Identity(), Matrix6d::Identity() * 0.01,
                                {{0.0f, 0.0f, 1.0f}, {0.5f, 0.0f, 1.0f}}, field, 0.15);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.points_unseen, 2);
  EXPECT_EQ(r.reason, "no point near the map");
}

// The partly seen floor of PosteriorXOnAPartlySeenFloor whose points beyond
// the seen edge (x > 1) have no plane (as a neighbourhood fit would find).
class NoPlaneBeyondTheEdge final : public DistanceQuery {
 public:
  void Distances(const Eigen::Vector3f* p, int n, float* out) const override { floor_.Distances(p, n, out); }
  void Planes(const Eigen::Vector3f* p, int n, bool* out, Eigen::Vector3f* normals, float* offsets_m) const override {
    floor_.Planes(p, n, out, normals, offsets_m);
    for (int i = 0; i < n; ++i) out[i] = out[i] && p[i].x() <= 1.0f;
  }

 private:
  testing::PartlySeenFloorField floor_;
};

TEST(GaussianParticleFilter, PlanesOnlyLeavesPointsWithoutAPlaneUnmeasured) {
  // Measured in the field, the floor points beyond the seen edge pull the
  // estimate back; not measured at all, they cannot.
  const NoPlaneBeyondTheEdge field;
  EXPECT_LT(PosteriorXOnAPartlySeenFloor(field, true, false, 5), -0.01);
  EXPECT_LT(std::abs(PosteriorXOnAPartlySeenFloor(field, true, true, 5)), 0.003);
}

TEST(GaussianParticleFilter, PlanesOnlyWithoutAnyPlaneIsAResult) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);  // no planes
  GpfOptions options;
  options.point_to_plane = true;
  options.planes_only = true;
  GaussianParticleFilter gpf(options);
  const GpfResult r = gpf.Match(Eigen::Isometry3d::Identity(), Matrix6d::Identity() * 0.01,
                                {{1.0f, 0.0f, -2.0f}, {0.0f, 1.0f, -2.0f}}, room);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "no point has a plane");
  std::string why;
  options.point_to_plane = false;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("planes_only"), std::string::npos);
}

TEST(GaussianParticleFilter, EmptyScanIsAResultNotACrash) {
  const testing::BoxRoomField room(5.0f, 3.0f, 2.0f);
  GaussianParticleFilter gpf(GpfOptions{});
  const GpfResult r = gpf.Match(Eigen::Isometry3d::Identity(), Matrix6d::Identity(), {}, room);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "no points to match");
}

}  // namespace
}  // namespace unimap::matching
