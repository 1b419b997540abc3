#pragma once
#include <Eigen/Core>

namespace unimap::matching {

// Distance from a point (map frame) to the nearest occupied surface,
// clamped by the implementation. Implementations must be thread-safe for
// concurrent reads.
class DistanceQuery {
 public:
  virtual ~DistanceQuery() = default;
  // Distances of n points, written to out[0..n).
  virtual void Distances(const Eigen::Vector3f* points_map, int n, float* out) const = 0;
  // Distances and their gradients (map frame, m per m) of n
  // points. The default differentiates Distances centrally with a step of
  // gradient_step_m(); fields with analytic gradients override it.
  virtual void DistancesAndGradients(const Eigen::Vector3f* points_map, int n, float* out,
                                     Eigen::Vector3f* gradients_map) const {
    Distances(points_map, n, out);
    const float h = gradient_step_m();
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3f probes[6];
      for (int a = 0; a < 3; ++a) {
        probes[2 * a] = points_map[i];
        probes[2 * a + 1] = points_map[i];
        probes[2 * a](a) += h;
        probes[2 * a + 1](a) -= h;
      }
      float d[6];
      Distances(probes, 6, d);
      for (int a = 0; a < 3; ++a) gradients_map[i](a) = (d[2 * a] - d[2 * a + 1]) / (2.0f * h);
    }
  }
  // The plane of the surface nearest to each of n points (map frame): out[i]
  // false when there is none (the default: fields without planes), else
  // normals[i] . x + offsets[i] is the signed height of x above it.
  virtual void Planes(const Eigen::Vector3f* /*points_map*/, int n, bool* out, Eigen::Vector3f* /*normals*/,
                      float* /*offsets_m*/) const {
    for (int i = 0; i < n; ++i) out[i] = false;
  }
  // Finite-difference step of the default DistancesAndGradients (m).
  virtual float gradient_step_m() const { return 0.01f; }
};

}  // namespace unimap::matching
