#include "map/CoarseField.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace unimap::map {
namespace {

constexpr float kFar = 1e20f;

// One line of the squared-distance transform, in place: f[i] <- min_j (f[j]
// + (i - j)^2) over the finite f[j] (kFar: no surface), the lower envelope
// of their parabolas (Felzenszwalb & Huttenlocher, "Distance transforms of
// sampled functions", 2012). v, z: scratch of f's size (z one more).
void TransformLine(std::vector<float>* f_io, std::vector<int>* v, std::vector<float>* z) {
  std::vector<float>& f = *f_io;
  const int n = static_cast<int>(f.size());
  const auto at = [](auto& values, int i) -> auto& { return values[static_cast<std::size_t>(i)]; };
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (at(f, q) >= kFar) continue;
    float s = -kFar;
    if (k >= 0) {
      for (;;) {
        const int p = at(*v, k);
        s = ((at(f, q) + static_cast<float>(q * q)) - (at(f, p) + static_cast<float>(p * p))) /
            (2.0f * static_cast<float>(q - p));
        if (s > at(*z, k)) break;
        --k;  // z[0] is -infinity: k stays >= 0
      }
    }
    ++k;
    at(*v, k) = q;
    at(*z, k) = k == 0 ? -kFar : s;
    at(*z, k + 1) = kFar;
  }
  if (k < 0) return;  // no surface on the line: every value stays kFar
  std::vector<float> out(f.size());
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (at(*z, k + 1) < static_cast<float>(q)) ++k;
    const int p = at(*v, k);
    at(out, q) = at(f, p) + static_cast<float>((q - p) * (q - p));
  }
  f.swap(out);
}

}  // namespace

std::shared_ptr<const DistanceField> CoarsenField(const DistanceField& fine, int factor, float clamp_m) {
  factor = std::max(factor, 1);
  if (fine.CellCount() == 0) return std::make_shared<const DistanceField>(clamp_m, fine.sequence());
  const Eigen::Vector3i dims = (fine.dims().array() + factor - 1) / factor;
  const std::size_t nx = static_cast<std::size_t>(dims.x()), ny = static_cast<std::size_t>(dims.y()),
                    nz = static_cast<std::size_t>(dims.z());
  std::vector<float> sq(nx * ny * nz, kFar);  // squared distance in coarse cells, x-y-z order
  const auto index = [&](std::size_t x, std::size_t y, std::size_t z) { return (x * ny + y) * nz + z; };
  fine.ForEachCellWithin(0.5f * fine.resolution(), [&](const Eigen::Vector3i& cell) {
    const Eigen::Vector3i c = cell / factor;
    sq[index(static_cast<std::size_t>(c.x()), static_cast<std::size_t>(c.y()), static_cast<std::size_t>(c.z()))] = 0.0f;
  });
  const std::size_t longest = std::max({nx, ny, nz});
  std::vector<float> f(longest), z(longest + 1);
  std::vector<int> v(longest);
  const auto pass = [&](std::size_t n, const auto& at) {
    f.resize(n);
    v.resize(n);
    z.resize(n + 1);
    for (std::size_t i = 0; i < n; ++i) f[i] = at(i);
    TransformLine(&f, &v, &z);
  };
  for (std::size_t x = 0; x < nx; ++x) {
    for (std::size_t y = 0; y < ny; ++y) {
      pass(nz, [&](std::size_t i) { return sq[index(x, y, i)]; });
      for (std::size_t i = 0; i < nz; ++i) sq[index(x, y, i)] = f[i];
    }
  }
  for (std::size_t x = 0; x < nx; ++x) {
    for (std::size_t z2 = 0; z2 < nz; ++z2) {
      pass(ny, [&](std::size_t i) { return sq[index(x, i, z2)]; });
      for (std::size_t i = 0; i < ny; ++i) sq[index(x, i, z2)] = f[i];
    }
  }
  for (std::size_t y = 0; y < ny; ++y) {
    for (std::size_t z2 = 0; z2 < nz; ++z2) {
      pass(nx, [&](std::size_t i) { return sq[index(i, y, z2)]; });
      for (std::size_t i = 0; i < nx; ++i) sq[index(i, y, z2)] = f[i];
    }
  }
  const float resolution = fine.resolution() * static_cast<float>(factor);
  std::vector<std::uint16_t> cells(sq.size());
  for (std::size_t i = 0; i < sq.size(); ++i) {
    cells[i] = DistanceField::Quantise(sq[i] >= kFar ? clamp_m : std::sqrt(sq[i]) * resolution, clamp_m);
  }
  return std::make_shared<const DistanceField>(fine.origin(), dims, resolution, clamp_m, std::move(cells),
                                               fine.sequence());
}

}  // namespace unimap::map
