#pragma once
#include <vector>

#include <Eigen/Core>

namespace unimap::graph {

// Surface normals of a point cloud for point-to-plane refinement: the points
// are binned in cubes of edge cell_m; each point gets the unit normal of the
// plane fitted to the points of its cube and the 26 around it (the smallest
// principal axis of their pooled scatter), or zero when they span no plane
// (smallest eigenvalue above planarity_ratio times the middle one: corners,
// edges, clutter) or number fewer than 5. Sign arbitrary.
std::vector<Eigen::Vector3f> LoopClosureNormals(const std::vector<Eigen::Vector3f>& points, double cell_m,
                                                double planarity_ratio);

}  // namespace unimap::graph
