#include "estimation/So3.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace unimap::estimation {
namespace {

TEST(So3, ExpAndLogAreInverse) {
  const Eigen::Vector3d theta(0.3, -0.2, 0.5);
  EXPECT_LT((LogQ(ExpQ(theta)) - theta).norm(), 1e-12);
  EXPECT_LT((Skew(theta) * Eigen::Vector3d(1, 2, 3) - theta.cross(Eigen::Vector3d(1, 2, 3))).norm(), 1e-15);
}

TEST(So3, LogGivesAngleTimesAxisOnBothHemispheres) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 3).normalized();
  for (const double angle : {0.0, 1e-9, 0.3, 2.0, M_PI - 1e-6}) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
    EXPECT_NEAR((LogQ(q) - angle * axis).norm(), 0.0, 1e-12);
    // -q is the same rotation.
    EXPECT_NEAR((LogQ(Eigen::Quaterniond(-q.coeffs())) - angle * axis).norm(), 0.0, 1e-12);
  }
}

TEST(So3, ApplyPoseErrorAddsPositionAndRotatesInTheBodyFrame) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  Eigen::Matrix<double, 6, 1> e;
  e << 0.1, -0.2, 0.3, 0.0, 0.0, 0.2;
  const Eigen::Isometry3d out = ApplyPoseError(T, e);
  EXPECT_TRUE(out.translation().isApprox(Eigen::Vector3d(1.1, 1.8, 3.3), 1e-15));
  // A body-frame yaw error on a yawed pose adds up: 0.7 + 0.2 about z.
  EXPECT_TRUE(out.linear().isApprox(Eigen::AngleAxisd(0.9, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-12));
  // A roll error turns about the body's x axis, not the world's.
  e << 0, 0, 0, 0.1, 0, 0;
  const Eigen::Vector3d body_x = T.linear().col(0);
  const Eigen::Isometry3d rolled = ApplyPoseError(T, e);
  EXPECT_TRUE(rolled.linear().col(0).isApprox(body_x, 1e-12));
  EXPECT_NEAR(rolled.linear().col(2).dot(Eigen::Vector3d::UnitZ()), std::cos(0.1), 1e-12);
}

}  // namespace
}  // namespace unimap::estimation
