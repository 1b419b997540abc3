#include "HeightfieldPrimitive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace unimap::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kMinStepM = 1e-4;            // smallest march step (grazes shorter than this are missed)
constexpr double kBisectionWidthM = 1e-9;     // final bracket width of a crossing
constexpr int kMaxNewtonSteps = 64;           // bracketed Newton steps before falling back to bisection
constexpr int kMaxProjectionIterations = 32;  // Gauss-Newton iterations in SurfaceDistance
// Margin of the height slab in Intersect, so that rounding cannot clip away a
// crossing at the slab's faces (a flat field has a slab of zero thickness).
constexpr double kSlabMarginM = 1e-7;

// Clips t to the slab lo <= o + t d <= hi; false when the ray misses it.
bool ClipSlab(double o, double d, double lo, double hi, double* t_min, double* t_max) {
  if (d == 0.0) return o >= lo && o <= hi;
  double t0 = (lo - o) / d;
  double t1 = (hi - o) / d;
  if (t0 > t1) std::swap(t0, t1);
  *t_min = std::max(*t_min, t0);
  *t_max = std::min(*t_max, t1);
  return *t_min <= *t_max;
}

// Smallest s > 0 with F + G s - (K / 2) s^2 = 0 (infinity if none): with
// |f| = F and slope G now and |f''| <= K, f cannot cross zero sooner.
double SafeStep(double F, double G, double K) {
  if (K == 0.0) return G < 0.0 ? F / -G : kInfinity;
  const double root = std::sqrt(G * G + 2.0 * K * F);
  return G <= 0.0 ? 2.0 * F / (root - G) : (G + root) / K;  // cancellation-free forms
}

// Smallest s > 0 with F + G s + (K / 2) s^2 = 0 (infinity if none): f has
// crossed zero by then.
double CertainCrossing(double F, double G, double K) {
  if (G >= 0.0) return kInfinity;
  const double discriminant = G * G - 2.0 * K * F;
  if (discriminant < 0.0) return kInfinity;
  return 2.0 * F / (std::sqrt(discriminant) - G);
}

// The unit normal (-h_x, -h_y, 1) / norm, turned against the ray direction d.
Eigen::Vector3d FacingNormal(const Eigen::Vector2d& gradient, const Eigen::Vector3d& d) {
  const Eigen::Vector3d n = Eigen::Vector3d(-gradient.x(), -gradient.y(), 1.0).normalized();
  return n.dot(d) > 0.0 ? Eigen::Vector3d(-n) : n;
}

}  // namespace

HeightfieldPrimitive::HeightfieldPrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector2d& size_m, double z0_m,
                                           std::vector<Wave> waves)
    : center_xy_(center_m.head<2>()), half_(0.5 * size_m), base_z_(center_m.z() + z0_m), waves_(std::move(waves)) {
  if (!center_m.allFinite() || !size_m.allFinite() || (size_m.array() <= 0.0).any() || !std::isfinite(z0_m)) {
    throw std::invalid_argument("HeightfieldPrimitive: center, size, z0 finite, size > 0");
  }
  for (const Wave& w : waves_) {
    if (!std::isfinite(w.amplitude_m) || !std::isfinite(w.kx_rad_m) || !std::isfinite(w.ky_rad_m) ||
        !std::isfinite(w.phi_rad) || !std::isfinite(w.psi_rad)) {
      throw std::invalid_argument("HeightfieldPrimitive: wave parameters must be finite");
    }
    amplitude_sum_ += std::abs(w.amplitude_m);
    slope_bound_ += std::abs(w.amplitude_m) * std::max(std::abs(w.kx_rad_m), std::abs(w.ky_rad_m));
    curvature_bound_ += std::abs(w.amplitude_m) * (w.kx_rad_m * w.kx_rad_m + w.ky_rad_m * w.ky_rad_m);
  }
}

double HeightfieldPrimitive::Height(double x, double y) const {
  double h = base_z_;
  for (const Wave& w : waves_) {
    h += w.amplitude_m * std::sin(w.kx_rad_m * x + w.phi_rad) * std::cos(w.ky_rad_m * y + w.psi_rad);
  }
  return h;
}

double HeightfieldPrimitive::HeightAndGradient(double x, double y, Eigen::Vector2d* gradient) const {
  double h = base_z_;
  gradient->setZero();
  for (const Wave& w : waves_) {
    const double ax = w.kx_rad_m * x + w.phi_rad;
    const double ay = w.ky_rad_m * y + w.psi_rad;
    const double sx = std::sin(ax);
    const double cx = std::cos(ax);
    const double sy = std::sin(ay);
    const double cy = std::cos(ay);
    h += w.amplitude_m * sx * cy;
    gradient->x() += w.amplitude_m * w.kx_rad_m * cx * cy;
    gradient->y() -= w.amplitude_m * w.ky_rad_m * sx * sy;
  }
  return h;
}

std::optional<RayHit> HeightfieldPrimitive::Intersect(const Ray& ray, double min_range_m, double max_range_m) const {
  const Eigen::Vector3d& o = ray.origin;
  const Eigen::Vector3d& d = ray.direction;
  // Restrict the ray to the bounding box (rectangle x [base - A, base + A],
  // plus a margin) and the range window.
  double t_lo = min_range_m;
  double t_hi = max_range_m;
  const Eigen::Vector2d lo = center_xy_ - half_;
  const Eigen::Vector2d hi = center_xy_ + half_;
  if (!ClipSlab(o.x(), d.x(), lo.x(), hi.x(), &t_lo, &t_hi) || !ClipSlab(o.y(), d.y(), lo.y(), hi.y(), &t_lo, &t_hi) ||
      !ClipSlab(o.z(), d.z(), base_z_ - amplitude_sum_ - kSlabMarginM, base_z_ + amplitude_sum_ + kSlabMarginM, &t_lo,
                &t_hi)) {
    return std::nullopt;
  }
  const Eigen::Vector2d d_xy = d.head<2>();
  const double horizontal = d_xy.norm();
  const double lipschitz = std::abs(d.z()) + slope_bound_ * horizontal;  // >= |f'|
  const double curvature = curvature_bound_ * horizontal * horizontal;   // >= |f''|
  if (lipschitz == 0.0) return std::nullopt;                             // horizontal ray over flat ground: no crossing
  // f(t) = z(t) - h(x(t), y(t)) and its slope f'(t) = d_z - grad h . d_xy.
  const auto evaluate = [&](double t, double* slope) {
    Eigen::Vector2d gradient;
    const double h = HeightAndGradient(o.x() + t * d.x(), o.y() + t * d.y(), &gradient);
    *slope = d.z() - gradient.dot(d_xy);
    return o.z() + t * d.z() - h;
  };
  const auto hit_at = [&](double t) {
    Eigen::Vector2d gradient;
    HeightAndGradient(o.x() + t * d.x(), o.y() + t * d.y(), &gradient);
    return RayHit{std::min(t, t_hi), FacingNormal(gradient, d), -1};
  };
  // Bisection of a bracket [lo_t, hi_t] with f(lo_t) < 0 iff lo_negative.
  const auto bisect = [&](double lo_t, double hi_t, bool lo_negative) {
    while (hi_t - lo_t > kBisectionWidthM) {
      const double mid = 0.5 * (lo_t + hi_t);
      if (mid <= lo_t || mid >= hi_t) break;  // bracket at floating-point resolution
      const double f_mid = o.z() + mid * d.z() - Height(o.x() + mid * d.x(), o.y() + mid * d.y());
      if (f_mid == 0.0) return hit_at(mid);
      ((f_mid < 0.0) == lo_negative ? lo_t : hi_t) = mid;
    }
    return hit_at(0.5 * (lo_t + hi_t));
  };

  double t = t_lo;
  double g = 0.0;
  double f = evaluate(t, &g);
  if (f == 0.0) {
    if (t > min_range_m) return hit_at(t);
    // Starting exactly on the surface: look for the next crossing just after.
    t = std::min(t + kBisectionWidthM, t_hi);
    f = evaluate(t, &g);
    if (f == 0.0) return t > min_range_m ? std::optional<RayHit>(hit_at(t)) : std::nullopt;
  }
  int newton_steps = 0;
  while (true) {
    // With F = |f(t)| and G its slope, Taylor's bound |f''| <= K gives, for s >= 0,
    //   F + G s - K s^2 / 2  <=  |f(t + s)| (while no crossing)  <=  F + G s + K s^2 / 2,
    // so no crossing before t + safe and (if G < 0) a crossing by t + certain.
    // F / L is a second lower bound. Near a simple crossing the two close in
    // quadratically (a one-sided Newton iteration that never overshoots).
    const double F = std::abs(f);
    const double G = f > 0.0 ? g : -g;
    const double safe = std::max(F / lipschitz, SafeStep(F, G, curvature));
    if (t + safe > t_hi) return std::nullopt;  // no crossing in [t, t_hi]
    const double certain = CertainCrossing(F, G, curvature);
    if (certain - safe <= kBisectionWidthM) return hit_at(t + 0.5 * (safe + certain));
    if (safe < kMinStepM) {
      if (t + certain <= t_hi) {  // a crossing is bracketed in [t + safe, t + certain]
        if (newton_steps++ >= kMaxNewtonSteps) return bisect(t + safe, t + certain, f < 0.0);
      } else {
        // Nearly tangent with no certain crossing: probe one minimum step.
        const double t_b = std::min(t + kMinStepM, t_hi);
        double g_b = 0.0;
        const double f_b = evaluate(t_b, &g_b);
        if (f_b == 0.0) return hit_at(t_b);
        if ((f_b < 0.0) != (f < 0.0)) return bisect(t, t_b, f < 0.0);
        if (t_b >= t_hi) return std::nullopt;
        t = t_b;
        f = f_b;
        g = g_b;
        continue;
      }
    }
    t += safe;
    f = evaluate(t, &g);
    if (f == 0.0) return hit_at(t);
  }
}

double HeightfieldPrimitive::SurfaceDistance(const Eigen::Vector3d& p) const {
  const Eigen::Vector2d lo = center_xy_ - half_;
  const Eigen::Vector2d hi = center_xy_ + half_;
  Eigen::Vector2d uv = p.head<2>().cwiseMax(lo).cwiseMin(hi);
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d g;
  for (int iteration = 0; iteration < kMaxProjectionIterations; ++iteration) {
    // Residual r = (u - x, v - y, h(u, v) - z), Jacobian J = [I; grad h^T].
    const double h = HeightAndGradient(uv.x(), uv.y(), &g);
    const Eigen::Vector2d r_xy = uv - p.head<2>();
    const double r_z = h - p.z();
    best = std::min(best, std::sqrt(r_xy.squaredNorm() + r_z * r_z));
    // Gauss-Newton step delta = -(J^T J)^-1 J^T r, with J^T J = I + g g^T inverted
    // by Sherman-Morrison: (I + g g^T)^-1 = I - g g^T / (1 + |g|^2).
    const Eigen::Vector2d jtr = r_xy + r_z * g;
    const Eigen::Vector2d delta = -(jtr - g * (g.dot(jtr) / (1.0 + g.squaredNorm())));
    const Eigen::Vector2d next = (uv + delta).cwiseMax(lo).cwiseMin(hi);
    if ((next - uv).squaredNorm() < 1e-24) break;
    uv = next;
  }
  return best;
}

Eigen::AlignedBox3d HeightfieldPrimitive::Bounds() const {
  const Eigen::Vector2d lo = center_xy_ - half_;
  const Eigen::Vector2d hi = center_xy_ + half_;
  return Eigen::AlignedBox3d(Eigen::Vector3d(lo.x(), lo.y(), base_z_ - amplitude_sum_),
                             Eigen::Vector3d(hi.x(), hi.y(), base_z_ + amplitude_sum_));
}

}  // namespace unimap::sim
