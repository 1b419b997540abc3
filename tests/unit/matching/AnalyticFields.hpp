#pragma once
// Distance fields with closed forms, for matcher tests.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "matching/DistanceQuery.hpp"

namespace unimap::matching::testing {

// Inside an axis-aligned box room [-hx, hx] x [-hy, hy] x [-hz, hz]: distance to the nearest wall.
class BoxRoomField final : public DistanceQuery {
 public:
  BoxRoomField(float hx, float hy, float hz) : h_(hx, hy, hz) {}
  void Distances(const Eigen::Vector3f* p, int n, float* out) const override {
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3f gap = h_ - p[i].cwiseAbs();
      out[i] = std::abs(gap.minCoeff());
    }
  }
  // Exact gradients: d = |h_k - |p_k|| for the nearest wall k.
  void DistancesAndGradients(const Eigen::Vector3f* p, int n, float* out, Eigen::Vector3f* gradients) const override {
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3f gap = h_ - p[i].cwiseAbs();
      int k = 0;
      gap.minCoeff(&k);
      out[i] = std::abs(gap(k));
      gradients[i].setZero();
      gradients[i](k) = -(gap(k) >= 0.0f ? 1.0f : -1.0f) * (p[i](k) >= 0.0f ? 1.0f : -1.0f);
    }
  }
  // Points on the walls (ceiling and floor included), fixed seed.
  std::vector<Eigen::Vector3f> SampleWalls(int n, unsigned seed) const {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_int_distribution<int> face(0, 5);
    std::vector<Eigen::Vector3f> out;
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3f p(u(rng) * h_.x(), u(rng) * h_.y(), u(rng) * h_.z());
      const int f = face(rng);
      p(f / 2) = (f % 2 == 0 ? 1.0f : -1.0f) * h_(f / 2);
      out.push_back(p);
    }
    return out;
  }

 private:
  Eigen::Vector3f h_;
};

// A single horizontal plane z = 0: distance |z|, no gradient in x or y.
class FloorField final : public DistanceQuery {
 public:
  void Distances(const Eigen::Vector3f* p, int n, float* out) const override {
    for (int i = 0; i < n; ++i) out[i] = std::abs(p[i].z());
  }
  // Exact gradients: (0, 0, sign z), +z on the plane itself.
  void DistancesAndGradients(const Eigen::Vector3f* p, int n, float* out, Eigen::Vector3f* gradients) const override {
    for (int i = 0; i < n; ++i) {
      out[i] = std::abs(p[i].z());
      gradients[i] = Eigen::Vector3f(0.0f, 0.0f, p[i].z() >= 0.0f ? 1.0f : -1.0f);
    }
  }
};

// Distance to a sphere of radius r at the origin, without analytic
// gradients (DistanceQuery's finite-difference default).
class SphereField final : public DistanceQuery {
 public:
  explicit SphereField(float r) : r_(r) {}
  void Distances(const Eigen::Vector3f* p, int n, float* out) const override {
    for (int i = 0; i < n; ++i) out[i] = std::abs(p[i].norm() - r_);
  }

 private:
  float r_;
};

// A map that has seen only part of a surface: the floor z = 0 for x <= 1
// (beyond it, distances are to its edge), a wall x = -2 and a wall y = -1.5.
// Planes() gives the plane of the nearest of the three, as CellPlanes does.
class PartlySeenFloorField final : public DistanceQuery {
 public:
  void Distances(const Eigen::Vector3f* p, int n, float* out) const override {
    for (int i = 0; i < n; ++i) out[i] = Nearest(p[i], nullptr);
  }
  void Planes(const Eigen::Vector3f* p, int n, bool* out, Eigen::Vector3f* normals, float* offsets_m) const override {
    for (int i = 0; i < n; ++i) {
      int k = 0;
      Nearest(p[i], &k);
      out[i] = true;
      normals[i] = Eigen::Vector3f::Unit(k == 0 ? 2 : k == 1 ? 0 : 1);
      offsets_m[i] = k == 0 ? 0.0f : k == 1 ? 2.0f : 1.5f;
    }
  }
  // Points on the whole floor (x in [-2, 3], also the unseen part) and on the walls, fixed seed.
  static std::vector<Eigen::Vector3f> SampleScan(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Eigen::Vector3f> out;
    for (int i = 0; i < n; ++i) {
      const float a = u(rng);
      const float b = u(rng);
      switch (i % 3) {
        case 0:
          out.emplace_back(-2.0f + 5.0f * a, -1.5f + 3.0f * b, 0.0f);
          break;  // floor
        case 1:
          out.emplace_back(-2.0f, -1.5f + 3.0f * a, 2.0f * b);
          break;  // wall x = -2
        default:
          out.emplace_back(-2.0f + 5.0f * a, -1.5f, 2.0f * b);
          break;  // wall y = -1.5
      }
    }
    return out;
  }

 private:
  // Distance to the nearest surface; *which (if not null): 0 floor, 1 wall x, 2 wall y.
  static float Nearest(const Eigen::Vector3f& p, int* which) {
    const float beyond = std::max(p.x() - 1.0f, 0.0f);
    const float d[3] = {std::sqrt(p.z() * p.z() + beyond * beyond), std::abs(p.x() + 2.0f), std::abs(p.y() + 1.5f)};
    const int k = static_cast<int>(std::min_element(d, d + 3) - d);
    if (which != nullptr) *which = k;
    return d[k];
  }
};

}  // namespace unimap::matching::testing
