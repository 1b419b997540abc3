#include "graph/LoopClosureNormals.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace unimap::graph {
namespace {

TEST(LoopClosureNormalsTest, PointsOnATiltedPlaneGetItsNormal) {
  const Eigen::Vector3f n = Eigen::Vector3f(0.3f, -0.2f, 1.0f).normalized();
  const Eigen::Vector3f u = n.unitOrthogonal();
  const Eigen::Vector3f v = n.cross(u);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      points.push_back(Eigen::Vector3f(1.0f, 2.0f, 0.5f) + 0.07f * static_cast<float>(i) * u +
                       0.07f * static_cast<float>(j) * v);
    }
  }
  const auto normals = LoopClosureNormals(points, 0.2, 0.1);
  ASSERT_EQ(normals.size(), points.size());
  for (const auto& normal : normals) EXPECT_NEAR(std::abs(normal.dot(n)), 1.0f, 1e-4f);
}

TEST(LoopClosureNormalsTest, CornersAndLonePointsHaveNoPlane) {
  // Three faces of a cube meeting at the origin, sampled every 5 cm.
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const float a = 0.05f * static_cast<float>(i) + 0.025f;
      const float b = 0.05f * static_cast<float>(j) + 0.025f;
      points.emplace_back(0.0f, a, b);
      points.emplace_back(a, 0.0f, b);
      points.emplace_back(a, b, 0.0f);
    }
  }
  points.emplace_back(5.0f, 5.0f, 5.0f);  // alone
  const auto normals = LoopClosureNormals(points, 0.2, 0.1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f& p = points[i];
    if (p.maxCoeff() < 0.2f) {
      EXPECT_EQ(normals[i], Eigen::Vector3f::Zero()) << p.transpose();  // at the corner
    } else if ((p.array() > 0.6f).count() == 2) {
      // Far from the other faces: the face's own normal.
      const int axis = p.x() == 0.0f ? 0 : (p.y() == 0.0f ? 1 : 2);
      EXPECT_NEAR(std::abs(normals[i][axis]), 1.0f, 1e-4f) << p.transpose();
    }
  }
  EXPECT_EQ(normals.back(), Eigen::Vector3f::Zero());
  EXPECT_TRUE(LoopClosureNormals({}, 0.2, 0.1).empty());
}

}  // namespace
}  // namespace unimap::graph
