// Where the odometry's distance field puts a wall (docs/robustness.md, "The
// tunnel with the rotating VLP-16"): a wall x = xf seen from one side, 20
// scans of returns with 1 cm of range noise into a SurfaceDistanceLayer of
// 0.3 m voxels; along x through the wall, where the exported field
// (DistanceTrilinear) has its minimum and what a point on the wall reads,
// for walls at ten fractions of their voxel. Built against a build of the
// repository (cmake --build build), from its root:
//   g++ -O2 -std=c++17 -Icore -Iinclude -I/usr/include/eigen3 docs/experiments/wall-offset.cpp \
//     build/core/map/libunimap_map.a -Lbuild/lib -lunimap_sdk -lz -loctomap -loctomath -lpthread \
//     -Wl,-rpath,$PWD/build/lib -o /tmp/wall-offset && /tmp/wall-offset
// With docs/experiments/tunnel-drift-trials.patch applied and rebuilt, run
// it with TRIAL_SIGNED=1 for signed fields.
#include <Eigen/Core>
#include <cstdio>
#include <random>
#include <vector>
#include "map/DistanceField.hpp"
#include "map/DistanceMapOptions.hpp"
#include "map/SurfaceDistanceLayer.hpp"
using namespace unimap::map;
int main() {
  const float h = 0.3f;
  for (float frac : {0.05f, 0.15f, 0.25f, 0.35f, 0.45f, 0.55f, 0.65f, 0.75f, 0.85f, 0.95f}) {
    DistanceMapOptions o;
    o.resolution_m = h;
    o.clamp_distance_m = 0.5;
    o.max_range_m = 20;
    SurfaceDistanceLayer layer(o);
    // wall at x = xf (voxel boundaries at multiples of h); frac = position within its voxel
    const float xf = 3.0f * h + frac * h;
    std::mt19937 rng(1);
    std::normal_distribution<float> n(0.f, 0.01f);
    const Eigen::Vector3f sensor(-2.0f, 0.05f, 0.05f);
    for (int s = 0; s < 20; ++s) {
      std::vector<Eigen::Vector3f> pts;
      for (float y = -2.0f; y <= 2.0f; y += 0.05f)
        for (float z = -2.0f; z <= 2.0f; z += 0.05f) {
          Eigen::Vector3f p(xf, y, z);
          Eigen::Vector3f r = (p - sensor).normalized();
          pts.push_back(p + r * n(rng));
        }
      layer.Insert(pts, sensor);
    }
    if (!layer.distances()) layer.EnableDistances();
    auto f = layer.Export(sensor, 0.0, 1);
    // scan along x at a few (y, z)
    float best_x = 0, best = 1e9, at_face = 0;
    int cnt = 0;
    double sum_best = 0, sum_face = 0, sum_g = 0;
    for (float y = -1.0f; y <= 1.0f; y += 0.13f)
      for (float z = -1.0f; z <= 1.0f; z += 0.17f) {
        best = 1e9;
        for (float x = xf - 0.3f; x <= xf + 0.3f; x += 0.002f) {
          const float d = f->DistanceTrilinear(Eigen::Vector3f(x, y, z), nullptr);
          if (d < best) {
            best = d;
            best_x = x;
          }
        }
        Eigen::Vector3f g;
        at_face = f->DistanceTrilinear(Eigen::Vector3f(xf, y, z), &g);
        sum_best += best_x - xf;
        sum_face += at_face;
        sum_g += g.x();
        ++cnt;
      }
    std::printf("frac %.2f  argmin - face %+.3f m  d at face %.3f  grad x at face %+.2f\n", frac, sum_best / cnt,
                sum_face / cnt, sum_g / cnt);
  }
}
