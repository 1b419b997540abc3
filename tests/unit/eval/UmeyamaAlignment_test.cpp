#include "eval/UmeyamaAlignment.hpp"

#include <random>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

TEST(UmeyamaAlignmentTest, RecoversARandomRigidTransform) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Isometry3d T_target_source = Eigen::Isometry3d::Identity();
    T_target_source.linear() =
        Eigen::Quaterniond(Eigen::Vector4d(uniform(rng), uniform(rng), uniform(rng), uniform(rng)).normalized())
            .toRotationMatrix();
    T_target_source.translation() = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    std::vector<Eigen::Vector3d> source;
    std::vector<Eigen::Vector3d> target;
    for (int i = 0; i < 50; ++i) {
      source.emplace_back(uniform(rng), uniform(rng), uniform(rng));
      target.push_back(T_target_source * source.back());
    }
    const RigidAlignment result = AlignRigid(source, target);
    EXPECT_LT((result.T_target_source.matrix() - T_target_source.matrix()).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT(result.rmse_m, 1e-9);
    EXPECT_NEAR(result.T_target_source.linear().determinant(), 1.0, 1e-12);
  }
}

TEST(UmeyamaAlignmentTest, PlanarPointsGiveARotationNotAReflection) {
  // Points in the plane z = 0 mirrored in y: the best proper rotation cannot
  // reproduce a reflection, the residual is known (pairs with y = +-1).
  const std::vector<Eigen::Vector3d> source = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
  std::vector<Eigen::Vector3d> target;
  for (const auto& p : source) target.emplace_back(p.x(), -p.y(), 0.0);
  const RigidAlignment result = AlignRigid(source, target);
  EXPECT_NEAR(result.T_target_source.linear().determinant(), 1.0, 1e-12);
  // Best fit: a rotation about x by pi (y -> -y, z -> -z), exact since z = 0.
  EXPECT_LT(result.rmse_m, 1e-12);
}

TEST(UmeyamaAlignmentTest, ResidualOfAScaledLineIsItsSpread) {
  // Target = 1.01 x source on a line: the rigid fit centres them, the
  // residuals are 0.01 (x_i - mean x), RMSE = 0.01 * std(x).
  std::vector<Eigen::Vector3d> source;
  std::vector<Eigen::Vector3d> target;
  for (int i = 0; i <= 10; ++i) {
    source.emplace_back(i, 0, 0);
    target.emplace_back(1.01 * i, 0, 0);
  }
  const double std_x = std::sqrt((11.0 * 11.0 - 1.0) / 12.0);  // population variance of 0..10: (m^2 - 1) / 12, m = 11
  EXPECT_NEAR(AlignRigid(source, target).rmse_m, 0.01 * std_x, 1e-12);
}

TEST(UmeyamaAlignmentTest, SimilarityRecoversARandomScaledTransform) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  std::uniform_real_distribution<double> scales(0.2, 5.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() =
        Eigen::Quaterniond(Eigen::Vector4d(uniform(rng), uniform(rng), uniform(rng), uniform(rng)).normalized())
            .toRotationMatrix();
    T.translation() = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    const double c = scales(rng);
    std::vector<Eigen::Vector3d> source;
    std::vector<Eigen::Vector3d> target;
    for (int i = 0; i < 50; ++i) {
      source.emplace_back(uniform(rng), uniform(rng), uniform(rng));
      target.push_back(c * (T.linear() * source.back()) + T.translation());
    }
    const std::optional<SimilarityAlignment> result = AlignSimilarity(source, target);
    ASSERT_TRUE(result.has_value());
    EXPECT_NEAR(result->scale, c, 1e-9 * c);
    EXPECT_LT((result->T_target_source.matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT(result->rmse_m, 1e-8);
  }
}

TEST(UmeyamaAlignmentTest, SimilarityOfAScaledLineFitsExactly) {
  // The line the rigid fit leaves a residual on (above): scale 1.01, no residual.
  std::vector<Eigen::Vector3d> source;
  std::vector<Eigen::Vector3d> target;
  for (int i = 0; i <= 10; ++i) {
    source.emplace_back(i, 0, 0);
    target.emplace_back(1.01 * i + 2.0, 0, 0);
  }
  const std::optional<SimilarityAlignment> result = AlignSimilarity(source, target);
  ASSERT_TRUE(result.has_value());
  EXPECT_NEAR(result->scale, 1.01, 1e-12);
  EXPECT_NEAR(result->T_target_source.translation().x(), 2.0, 1e-12);
  EXPECT_LT(result->rmse_m, 1e-12);
}

TEST(UmeyamaAlignmentTest, SimilarityHasNoScaleForAPointOrOntoAPoint) {
  const std::vector<Eigen::Vector3d> still(5, Eigen::Vector3d(1.0, 2.0, 3.0));
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  EXPECT_FALSE(AlignSimilarity(still, line).has_value());
  EXPECT_FALSE(AlignSimilarity(line, still).has_value());
}

TEST(UmeyamaAlignmentTest, RejectsMismatchedOrEmptyInput) {
  EXPECT_THROW(AlignRigid({}, {}), InputError);
  EXPECT_THROW(AlignSimilarity({{0, 0, 0}}, {}), InputError);
  EXPECT_THROW(AlignRigid({Eigen::Vector3d::Zero()}, {}), InputError);
}

}  // namespace
}  // namespace unimap::eval
