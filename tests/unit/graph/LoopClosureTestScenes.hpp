#pragma once
// Synthetic worlds for the loop-closure tests: scenes of axis-aligned boxes,
// their surfaces sampled on a grid (the submap) and a spinning LiDAR ray-cast
// against them (the scan). Everything is deterministic.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Geometry>

namespace unimap::graph::test {

struct Box {
  Eigen::Vector3f lo;  // min corner (m)
  Eigen::Vector3f hi;  // max corner (m)
};
using Scene = std::vector<Box>;

inline constexpr float kPi = 3.14159265358979f;

// A closed room [0, sx] x [0, sy] x [0, sz] with 0.2 m thick walls.
inline Scene Room(float sx, float sy, float sz) {
  const float w = 0.2f;
  return {
      {{-w, -w, -w}, {sx + w, sy + w, 0.0f}},    // floor
      {{-w, -w, sz}, {sx + w, sy + w, sz + w}},  // ceiling
      {{-w, -w, 0.0f}, {0.0f, sy + w, sz}},      // wall x = 0
      {{sx, -w, 0.0f}, {sx + w, sy + w, sz}},    // wall x = sx
      {{0.0f, -w, 0.0f}, {sx, 0.0f, sz}},        // wall y = 0
      {{0.0f, sy, 0.0f}, {sx, sy + w, sz}},      // wall y = sy
  };
}

// A 24 m x 10 m x 3 m hall with irregular furniture and pillars (no
// repetition): a place a scan matches in one way only.
inline Scene DistinctiveHall() {
  Scene scene = Room(24.0f, 10.0f, 3.0f);
  const std::vector<Box> features = {
      {{2.0f, 1.5f, 0.0f}, {3.2f, 2.3f, 1.0f}},     // crate
      {{6.0f, 7.0f, 0.0f}, {6.5f, 7.5f, 3.0f}},     // pillar
      {{9.5f, 0.0f, 0.0f}, {11.0f, 0.6f, 2.0f}},    // cabinet on the wall
      {{13.0f, 4.0f, 0.0f}, {13.4f, 6.5f, 1.2f}},   // low wall
      {{17.0f, 2.0f, 0.0f}, {17.6f, 2.4f, 3.0f}},   // pillar
      {{20.0f, 7.0f, 0.0f}, {22.5f, 8.0f, 0.8f}},   // table
      {{4.0f, 9.2f, 0.0f}, {5.0f, 10.0f, 2.2f}},    // shelf
      {{15.0f, 8.0f, 0.0f}, {15.3f, 10.0f, 3.0f}},  // partition
      {{8.0f, 3.0f, 2.4f}, {12.0f, 3.4f, 3.0f}},    // ceiling beam
      {{0.0f, 4.0f, 0.0f}, {0.8f, 5.5f, 1.5f}},     // counter
  };
  scene.insert(scene.end(), features.begin(), features.end());
  return scene;
}

// A 60 m corridor along x (3 m wide, 3 m high) with identical pillars on
// both walls and a ceiling beam every period_m, nothing else.
inline Scene PillarCorridor(float period_m) {
  Scene scene = Room(60.0f, 3.0f, 3.0f);
  for (float x = period_m; x < 60.0f - 0.5f; x += period_m) {
    scene.push_back({{x, 0.0f, 0.0f}, {x + 0.3f, 0.3f, 3.0f}});
    scene.push_back({{x, 2.7f, 0.0f}, {x + 0.3f, 3.0f, 3.0f}});
    scene.push_back({{x, 0.0f, 2.6f}, {x + 0.3f, 3.0f, 3.0f}});
  }
  return scene;
}

// A different place: a 7 m x 5 m store room with a column and crates.
inline Scene StoreRoom(float height_m) {
  Scene scene = Room(7.0f, 5.0f, height_m);
  scene.push_back({{3.0f, 2.0f, 0.0f}, {3.6f, 2.6f, height_m}});
  scene.push_back({{0.0f, 0.0f, 0.0f}, {1.5f, 1.0f, 1.8f}});
  scene.push_back({{5.5f, 3.5f, 0.0f}, {7.0f, 5.0f, 1.0f}});
  return scene;
}

inline bool StrictlyInside(const Box& b, const Eigen::Vector3f& p) {
  const float e = 1e-4f;
  return (p.array() > b.lo.array() + e).all() && (p.array() < b.hi.array() - e).all();
}

// The inside of a scene built on Room (its first two boxes: floor, ceiling).
inline Box RoomInterior(const Scene& scene) {
  const float w = 0.2f;
  return {{scene[0].lo.x() + w, scene[0].lo.y() + w, scene[0].hi.z()},
          {scene[1].hi.x() - w, scene[1].hi.y() - w, scene[1].lo.z()}};
}

// Samples of every box face on a grid of spacing_m (cell centres) within
// the room's interior (what a sensor inside can see), except those strictly
// inside another box (hidden).
inline std::vector<Eigen::Vector3f> SampleSurfaces(const Scene& scene, float spacing_m) {
  const Box interior = RoomInterior(scene);
  const float tolerance = 1e-3f;
  std::vector<Eigen::Vector3f> points;
  for (std::size_t b = 0; b < scene.size(); ++b) {
    const Box& box = scene[b];
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      const int nu = std::max(1, static_cast<int>(std::floor((box.hi[u] - box.lo[u]) / spacing_m)));
      const int nv = std::max(1, static_cast<int>(std::floor((box.hi[v] - box.lo[v]) / spacing_m)));
      for (float side : {box.lo[axis], box.hi[axis]}) {
        for (int i = 0; i < nu; ++i) {
          for (int j = 0; j < nv; ++j) {
            Eigen::Vector3f p;
            p[axis] = side;
            p[u] = box.lo[u] + (static_cast<float>(i) + 0.5f) * (box.hi[u] - box.lo[u]) / static_cast<float>(nu);
            p[v] = box.lo[v] + (static_cast<float>(j) + 0.5f) * (box.hi[v] - box.lo[v]) / static_cast<float>(nv);
            if ((p.array() < interior.lo.array() - tolerance).any() ||
                (p.array() > interior.hi.array() + tolerance).any()) {
              continue;
            }
            bool hidden = false;
            for (std::size_t o = 0; o < scene.size() && !hidden; ++o) hidden = o != b && StrictlyInside(scene[o], p);
            if (!hidden) points.push_back(p);
          }
        }
      }
    }
  }
  return points;
}

// Distance along the ray origin + t dir to the nearest box it enters
// (slab method); infinity when none.
inline float CastRay(const Scene& scene, const Eigen::Vector3f& origin, const Eigen::Vector3f& dir) {
  float nearest = std::numeric_limits<float>::infinity();
  for (const Box& box : scene) {
    float enter = -std::numeric_limits<float>::infinity();
    float leave = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (std::abs(dir[a]) < 1e-9f) {
        if (origin[a] < box.lo[a] || origin[a] > box.hi[a]) enter = leave + 1.0f;
        continue;
      }
      float t0 = (box.lo[a] - origin[a]) / dir[a];
      float t1 = (box.hi[a] - origin[a]) / dir[a];
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
    }
    if (enter <= leave && enter > 0.0f) nearest = std::min(nearest, enter);
  }
  return nearest;
}

// A spinning LiDAR at T_world_body: `beams` elevations evenly in
// [-max_elevation, +max_elevation], `azimuths` per turn, hits within
// max_range_m, in the body frame, with Gaussian noise of noise_m per axis.
inline std::vector<Eigen::Vector3f> SimulateScan(const Scene& scene, const Eigen::Isometry3d& T_world_body,
                                                 float max_range_m, float noise_m = 0.0f, std::uint64_t seed = 7,
                                                 int beams = 32, int azimuths = 720, float max_elevation_rad = 0.7f) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> noise(0.0f, 1.0f);
  const Eigen::Isometry3f T = T_world_body.cast<float>();
  std::vector<Eigen::Vector3f> points;
  for (int b = 0; b < beams; ++b) {
    const float elevation =
        -max_elevation_rad + 2.0f * max_elevation_rad * static_cast<float>(b) / static_cast<float>(beams - 1);
    for (int k = 0; k < azimuths; ++k) {
      const float azimuth = 2.0f * kPi * static_cast<float>(k) / static_cast<float>(azimuths);
      const Eigen::Vector3f dir_body(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                     std::sin(elevation));
      const float range = CastRay(scene, T.translation(), T.linear() * dir_body);
      if (!(range <= max_range_m)) continue;
      Eigen::Vector3f p = range * dir_body;
      if (noise_m > 0.0f) p += noise_m * Eigen::Vector3f(noise(rng), noise(rng), noise(rng));
      points.push_back(p);
    }
  }
  return points;
}

// Points mapped by T (e.g. world -> submap frame).
inline std::vector<Eigen::Vector3f> Transform(const Eigen::Isometry3d& T, const std::vector<Eigen::Vector3f>& points) {
  const Eigen::Isometry3f Tf = T.cast<float>();
  std::vector<Eigen::Vector3f> out;
  out.reserve(points.size());
  for (const Eigen::Vector3f& p : points) out.push_back(Tf * p);
  return out;
}

// A pose from position and roll, pitch, yaw (rad): R = Rz(yaw) Ry(pitch) Rx(roll).
inline Eigen::Isometry3d Pose(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// Rotation angle between two poses (rad).
inline double RotationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace unimap::graph::test
