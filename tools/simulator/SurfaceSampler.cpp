#include "SurfaceSampler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace unimap::sim {
namespace {

// Voxel indices are packed 21 bits per axis: |index| < 2^20 (+-52 km at 0.05 m).
constexpr std::int64_t kMaxIndex = std::int64_t{1} << 20;

// An insert-only set of packed voxel keys: open addressing with linear
// probing (a node-based std::unordered_set is several times slower here).
// Slots hold key + 1, so 0 marks an empty slot.
class VoxelSet {
 public:
  explicit VoxelSet(std::size_t expected = 1024) : slots_(Capacity(expected), 0) {}
  // True when key was not in the set (and is now).
  bool Insert(std::uint64_t key) {
    if (2 * (size_ + 1) > slots_.size()) Grow();
    if (!Place(slots_, key + 1)) return false;
    ++size_;
    return true;
  }

 private:
  static std::size_t Capacity(std::size_t expected) {
    std::size_t c = 1024;
    while (c < 2 * expected) c *= 2;
    return c;
  }
  // SplitMix64 finaliser: spreads neighbouring voxels over the table.
  static std::uint64_t Mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Puts stored (key + 1) into table; false when it was there already.
  static bool Place(std::vector<std::uint64_t>& table, std::uint64_t stored) {
    const std::size_t mask = table.size() - 1;
    for (std::size_t i = static_cast<std::size_t>(Mix(stored)) & mask;; i = (i + 1) & mask) {
      if (table[i] == stored) return false;
      if (table[i] == 0) {
        table[i] = stored;
        return true;
      }
    }
  }
  void Grow() {
    std::vector<std::uint64_t> bigger(slots_.size() * 2, 0);
    for (const std::uint64_t stored : slots_) {
      if (stored != 0) Place(bigger, stored);
    }
    slots_.swap(bigger);
  }

  std::vector<std::uint64_t> slots_;  // power-of-two size, at most half full
  std::size_t size_ = 0;              // keys held
};

// A hit and its voxel.
struct KeyedPoint {
  Eigen::Vector3d p;      // on a surface, world frame
  std::uint64_t key = 0;  // its packed voxel index
};

SurfaceSamplerOptions Validated(const SurfaceSamplerOptions& o) {
  auto fail = [](const std::string& why) { throw std::invalid_argument("SurfaceSampler: " + why); };
  if (o.directions_per_viewpoint < 1) fail("directions_per_viewpoint must be >= 1");
  if (!(std::isfinite(o.min_range_m) && o.min_range_m >= 0.0)) fail("min_range_m must be finite and >= 0");
  if (!(std::isfinite(o.max_range_m) && o.max_range_m > o.min_range_m)) {
    fail("max_range_m must be finite and > min_range_m");
  }
  if (!(std::isfinite(o.voxel_m) && o.voxel_m > 0.0)) fail("voxel_m must be finite and > 0");
  return o;
}

}  // namespace

SurfaceSampler::SurfaceSampler(const World& world, SurfaceSamplerOptions options)
    : world_(world), options_(Validated(options)), directions_(FibonacciSphere(options_.directions_per_viewpoint)) {
  if (!world_.built()) throw std::invalid_argument("SurfaceSampler: the world is not built (call World::Build)");
}

std::vector<Eigen::Vector3d> SurfaceSampler::FibonacciSphere(int n) {
  if (n < 1) throw std::invalid_argument("SurfaceSampler::FibonacciSphere: n must be >= 1");
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<Eigen::Vector3d> directions;
  directions.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return directions;
}

std::vector<Eigen::Vector3d> SurfaceSampler::Sample(const std::vector<Eigen::Vector3d>& viewpoints) const {
  for (const Eigen::Vector3d& v : viewpoints) {
    if (!v.allFinite()) throw std::invalid_argument("SurfaceSampler::Sample: a viewpoint is not finite");
  }
  const double inv_voxel = 1.0 / options_.voxel_m;
  auto key_of = [inv_voxel](const Eigen::Vector3d& p) {
    std::uint64_t key = 0;
    for (int j = 0; j < 3; ++j) {
      const double index = std::floor(p[j] * inv_voxel);
      if (!(std::abs(index) < static_cast<double>(kMaxIndex))) {
        throw std::invalid_argument("SurfaceSampler: a hit lies too far from the origin for the voxel size");
      }
      key = (key << 21) | static_cast<std::uint64_t>(static_cast<std::int64_t>(index) + kMaxIndex);
    }
    return key;
  };
  // Contiguous blocks of viewpoints, each deduplicated on its own thread
  // (the first hit of a voxel within the block is kept).
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::max<std::size_t>(
      1, std::min<std::size_t>(options_.threads > 0 ? options_.threads : hardware, viewpoints.size()));
  std::vector<std::vector<KeyedPoint>> blocks(threads);
  std::vector<std::exception_ptr> errors(threads);
  auto cast_block = [&](std::size_t b) {
    try {
      const std::size_t begin = viewpoints.size() * b / threads;
      const std::size_t end = viewpoints.size() * (b + 1) / threads;
      VoxelSet seen;
      Ray ray;
      for (std::size_t v = begin; v < end; ++v) {
        ray.origin = viewpoints[v];
        for (const Eigen::Vector3d& d : directions_) {
          ray.direction = d;
          const std::optional<RayHit> hit = world_.Cast(ray, options_.min_range_m, options_.max_range_m);
          if (!hit) continue;
          const Eigen::Vector3d p = ray.origin + hit->range_m * d;
          const std::uint64_t key = key_of(p);
          if (seen.Insert(key)) blocks[b].push_back({p, key});
        }
      }
    } catch (...) {
      errors[b] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  for (std::size_t b = 1; b < threads; ++b) workers.emplace_back(cast_block, b);
  cast_block(0);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }

  // Merge in block order: the first of a voxel over all blocks is the first
  // of the lowest block holding it, exactly what one thread would keep.
  std::size_t total = 0;
  for (const auto& block : blocks) total += block.size();
  VoxelSet seen(total);
  std::vector<Eigen::Vector3d> points;
  points.reserve(total);
  for (const auto& block : blocks) {
    for (const KeyedPoint& k : block) {
      if (seen.Insert(k.key)) points.push_back(k.p);
    }
  }
  return points;
}

}  // namespace unimap::sim
