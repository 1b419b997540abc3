#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "Primitive.hpp"

namespace unimap::sim {

// Uneven ground: the two-sided surface
//   z = h(x, y) = base + sum_k a_k sin(kx_k x + phi_k) cos(ky_k y + psi_k)
// over the rectangle |x - cx| <= lx / 2, |y - cy| <= ly / 2 (x, y world
// coordinates, so neighbouring tiles with the same waves join seamlessly;
// base = center.z + z0). No side walls: outside the rectangle there is nothing.
//
// Slope bound G = sum_k |a_k| max(|kx_k|, |ky_k|) >= |grad h| everywhere
// (each term's gradient has norm |a| sqrt(kx^2 c^2 C^2 + ky^2 s^2 S^2) <= |a| max(|kx|, |ky|)).
// Curvature bound K = sum_k |a_k| (kx_k^2 + ky_k^2) >= ||Hessian h|| (each
// term's Hessian has Frobenius norm <= |a| (kx^2 + ky^2)).
class HeightfieldPrimitive final : public Primitive {
 public:
  // One term of the sum.
  struct Wave {
    double amplitude_m = 0.0;  // a_k
    double kx_rad_m = 0.0;     // kx_k, wavenumber along x (rad/m)
    double ky_rad_m = 0.0;     // ky_k, wavenumber along y (rad/m)
    double phi_rad = 0.0;      // phase of the x factor
    double psi_rad = 0.0;      // phase of the y factor
  };

  // center_m: rectangle center (x, y) and reference height z; size_m: (lx, ly)
  // > 0; z0_m: height offset added to center.z; waves: any number of terms.
  // All values finite; throws std::invalid_argument otherwise.
  HeightfieldPrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector2d& size_m, double z0_m,
                       std::vector<Wave> waves);

  // Marches along the ray (clipped to the bounds) on f(t) = z(t) - h(x(t), y(t))
  // with steps that cannot jump over a crossing: the larger of |f| / L,
  // L = |d_z| + G |d_xy| >= |f'|, and the Taylor bound from |f''| <= K |d_xy|^2.
  // The Taylor bound also brackets the crossing from above, so near a simple
  // crossing the march is a one-sided Newton iteration, stopped when the
  // bracket is below 1e-9 m (bisection if it stalls). Where no crossing is
  // certain and the safe step drops below 1e-4 m (the ray grazes the surface),
  // it probes 1e-4 m steps and bisects a sign change to below 1e-9 m; a pair
  // of crossings closer than 1e-4 m (a graze) can be missed.
  std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const override;
  // Not closed-form. Returns the distance to a real surface point (so an upper
  // bound on the true distance): the best point of a projected Gauss-Newton
  // descent on |p - (u, v, h(u, v))|^2 from the vertical foot point (x, y
  // clamped to the rectangle). It equals the true distance when that descent
  // reaches the global nearest point, which holds for points closer to the
  // surface than its smallest radius of curvature 1 / K
  // (the case for map-accuracy metrics). Over the rectangle it is never below
  // the lower bound |z - h(x, y)| / sqrt(1 + G^2).
  double SurfaceDistance(const Eigen::Vector3d& p) const override;
  Eigen::AlignedBox3d Bounds() const override;
  std::string Kind() const override { return "heightfield"; }

  // h(x, y) (also outside the rectangle, where it is the analytic extension).
  double Height(double x, double y) const;
  // Slope bound G (see the class comment).
  double slope_bound() const { return slope_bound_; }
  // Curvature bound K (see the class comment).
  double curvature_bound() const { return curvature_bound_; }
  const std::vector<Wave>& waves() const { return waves_; }

 private:
  // h and its gradient at (x, y).
  double HeightAndGradient(double x, double y, Eigen::Vector2d* gradient) const;

  Eigen::Vector2d center_xy_;     // rectangle center (m)
  Eigen::Vector2d half_;          // rectangle half sizes (m)
  double base_z_;                 // mean height: center.z + z0 (m)
  std::vector<Wave> waves_;       // the sum's terms
  double amplitude_sum_ = 0.0;    // sum_k |a_k|: h stays within base +- this
  double slope_bound_ = 0.0;      // G
  double curvature_bound_ = 0.0;  // K
};

}  // namespace unimap::sim
