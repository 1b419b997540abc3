// Stage micro-benchmarks on fixed inputs (StageInputs): deskew, scan
// downsampling, particle filter match, map update (surface elements,
// distance waves, field export), and distance lookups. Each case runs on a
// simulated scenario / payload pair; figures in docs/benchmarks.md. Also
// a candidate distance map the issue asked to compare (a batch exact EDT).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "BenchCases.hpp"
#include "StageInputs.hpp"
#include "map/SurfaceDistanceLayer.hpp"
#include "matching/GaussianParticleFilter.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "pipeline/FieldDistanceQuery.hpp"

namespace unimap::bench {
namespace {

// The map after every key scan of the inputs.
std::unique_ptr<map::SurfaceDistanceLayer> FullMap(const StageInputs& in) {
  auto layer = std::make_unique<map::SurfaceDistanceLayer>(in.options.map);
  for (const KeyScanInput& key : in.key_scans) layer->Insert(key.points_map, key.sensor_map);
  return layer;
}

void BM_Deskew(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  const PayloadPlugin& plugin = *in.platform.plugin.plugin;
  const MotionQuery truth = [&in](double t) { return in.truth.At(t); };
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(plugin.Deskew(in.raw_scans[i], in.encoder, truth));
    i = (i + 1) % in.raw_scans.size();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ScanDownsample(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  const matching::GpfOptions& gpf = in.options.gpf;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(matching::VoxelDownsample(in.body_scans[i], gpf.voxel_size_m, gpf.max_points, i));
    i = (i + 1) % in.body_scans.size();
  }
  state.SetItemsProcessed(state.iterations());
}

// Every key scan into a fresh map, with a field export after each (as the
// odometry map does); items are key scans.
void BM_MapUpdate(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  map::SurfaceDistanceCounts counts;
  for (auto _ : state) {
    map::SurfaceDistanceLayer layer(in.options.map);
    std::uint64_t sequence = 0;
    for (const KeyScanInput& key : in.key_scans) {
      layer.Insert(key.points_map, key.sensor_map);
      benchmark::DoNotOptimize(layer.Export(key.sensor_map, in.options.map.max_range_m, ++sequence));
    }
    counts = layer.counts();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.key_scans.size()));
  const double keys = static_cast<double>(in.key_scans.size());
  state.counters["points/key"] = static_cast<double>(counts.points_added) / keys;
  state.counters["waves/key"] = static_cast<double>(counts.waves) / keys;
  state.counters["cells/key"] = static_cast<double>(counts.cells_claimed) / keys;
  state.counters["blocks/key"] = static_cast<double>(counts.blocks_computed) / keys;
  state.counters["elements"] = static_cast<double>(counts.elements);
  state.counters["cleared/key"] = static_cast<double>(counts.voxels_cleared) / keys;
  state.counters["surface_ms"] = 1e3 * (counts.surface_s - counts.carve_s);
  state.counters["carve_ms"] = 1e3 * counts.carve_s;
  state.counters["distance_ms"] = 1e3 * counts.distance_s;
  state.counters["export_ms"] = 1e3 * counts.export_s;
}

// A growing submap becoming the matching one: every element propagated at once.
void BM_MapEnableDistances(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  for (auto _ : state) {
    state.PauseTiming();
    map::DistanceMapOptions growing = in.options.map;
    growing.compute_distances = false;
    map::SurfaceDistanceLayer layer(growing);
    for (const KeyScanInput& key : in.key_scans) layer.Insert(key.points_map, key.sensor_map);
    state.ResumeTiming();
    layer.EnableDistances();
    benchmark::DoNotOptimize(layer.Export(in.key_scans.back().sensor_map, in.options.map.max_range_m, 1));
  }
}

// Felzenszwalb & Huttenlocher's exact squared distance transform of a
// sampled function along one line of n values (f: 0 on a surface voxel,
// kEmpty elsewhere); d receives it. v, z: scratch of n and n + 1 entries.
constexpr float kEmpty = 1e20f;
void DistanceTransform1d(const float* f, int n, std::size_t stride, float* d, int* v, float* z) {
  int k = 0;
  v[0] = 0;
  z[0] = -kEmpty;
  z[1] = kEmpty;
  for (int q = 1; q < n; ++q) {
    const float fq = f[static_cast<std::size_t>(q) * stride];
    float s = 0.0f;
    while (true) {
      const int p = v[k];
      const float fp = f[static_cast<std::size_t>(p) * stride];
      s = ((fq + static_cast<float>(q) * static_cast<float>(q)) -
           (fp + static_cast<float>(p) * static_cast<float>(p))) /
          (2.0f * static_cast<float>(q - p));
      if (s > z[k] || k == 0) break;
      --k;
    }
    if (s <= z[k] && k == 0) {
      v[0] = q;
      z[0] = -kEmpty;
      z[1] = kEmpty;
      continue;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kEmpty;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < static_cast<float>(q)) ++k;
    const float dq = static_cast<float>(q - v[k]);
    d[static_cast<std::size_t>(q) * stride] = dq * dq + f[static_cast<std::size_t>(v[k]) * stride];
  }
}

// The candidate the issue names beside the incremental layer (docs/mapping.md,
// "Distance map candidates"): the exact squared distance to the nearest
// occupied voxel centre, by three 1D passes over a dense grid around the
// occupied voxels of the 10 s map (within the odometry box around the last
// sensor position, plus the clamp), recomputed whole; as a submap's batch
// when it becomes the matching one, or per key scan. Items are cells.
void BM_BatchDistanceTransform(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  const auto layer = FullMap(in);
  const double res = in.options.map.resolution_m;
  const Eigen::Vector3f sensor = in.key_scans.back().sensor_map;
  const float half = static_cast<float>(in.options.map.max_range_m);
  std::vector<Eigen::Vector3i> keys;
  Eigen::Vector3i low = Eigen::Vector3i::Constant(1 << 30);
  Eigen::Vector3i high = Eigen::Vector3i::Constant(-(1 << 30));
  for (const Eigen::Vector3f& c : layer->VoxelCenters()) {
    if (((c - sensor).cwiseAbs().array() > half).any()) continue;
    const Eigen::Vector3i k = (c.cast<double>() / res).array().floor().cast<int>();
    keys.push_back(k);
    low = low.cwiseMin(k);
    high = high.cwiseMax(k);
  }
  const int margin = static_cast<int>(std::ceil(in.options.map.clamp_distance_m / res)) + 1;
  low.array() -= margin;
  high.array() += margin;
  const Eigen::Vector3i dims = (high - low).array() + 1;
  const std::size_t nx = static_cast<std::size_t>(dims.x());
  const std::size_t ny = static_cast<std::size_t>(dims.y());
  const std::size_t nz = static_cast<std::size_t>(dims.z());
  std::vector<float> grid(nx * ny * nz);
  std::vector<float> out(grid.size());
  const int longest = dims.maxCoeff();
  std::vector<int> v(static_cast<std::size_t>(longest));
  std::vector<float> z(static_cast<std::size_t>(longest) + 1);
  for (auto _ : state) {
    std::fill(grid.begin(), grid.end(), kEmpty);
    for (const Eigen::Vector3i& k : keys) {
      const Eigen::Vector3i l = k - low;
      grid[(static_cast<std::size_t>(l.x()) * ny + static_cast<std::size_t>(l.y())) * nz +
           static_cast<std::size_t>(l.z())] = 0.0f;
    }
    // Along z (contiguous), then y, then x, each pass reading the previous one's output.
    for (std::size_t x = 0; x < nx; ++x) {
      for (std::size_t y = 0; y < ny; ++y) {
        const std::size_t first = (x * ny + y) * nz;
        DistanceTransform1d(&grid[first], static_cast<int>(nz), 1, &out[first], v.data(), z.data());
      }
    }
    for (std::size_t x = 0; x < nx; ++x) {
      for (std::size_t iz = 0; iz < nz; ++iz) {
        const std::size_t first = x * ny * nz + iz;
        DistanceTransform1d(&out[first], static_cast<int>(ny), nz, &grid[first], v.data(), z.data());
      }
    }
    for (std::size_t y = 0; y < ny; ++y) {
      for (std::size_t iz = 0; iz < nz; ++iz) {
        const std::size_t first = y * nz + iz;
        DistanceTransform1d(&grid[first], static_cast<int>(nx), ny * nz, &out[first], v.data(), z.data());
      }
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(grid.size()));
  state.counters["cells"] = static_cast<double>(grid.size());
  state.counters["voxels"] = static_cast<double>(keys.size());
}

// The particle filter (with its refinement) matching each scan at its true
// pose in the map of all key scans; items are scans.
void BM_Match(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  const auto layer = FullMap(in);
  const auto field = layer->Export(in.key_scans.back().sensor_map, 0.0, 1);
  const pipeline::FieldDistanceQuery query(field, in.options.trilinear_distance);
  matching::GaussianParticleFilter gpf(in.options.gpf);
  matching::Matrix6d covariance = matching::Matrix6d::Zero();
  covariance.diagonal() << 4e-4, 4e-4, 4e-4, 4e-6, 4e-6, 4e-6;  // 2 cm, 0.11 deg
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        gpf.Match(in.body_poses[i], covariance, in.body_scans[i], query, in.options.max_predicted_distance_m));
    i = (i + 1) % in.body_scans.size();
  }
  state.SetItemsProcessed(state.iterations());
}

// Trilinear lookups with gradients at points near the surfaces.
void BM_TrilinearLookup(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  const auto field = FullMap(in)->Export(in.key_scans.back().sensor_map, 0.0, 1);
  std::vector<Eigen::Vector3f> probes;
  std::mt19937 rng(7);
  std::normal_distribution<float> offset(0.0f, 0.1f);
  for (const Eigen::Vector3f& p : in.key_scans.front().points_map) {
    probes.push_back(p + Eigen::Vector3f(offset(rng), offset(rng), offset(rng)));
  }
  std::size_t i = 0;
  Eigen::Vector3f gradient;
  for (auto _ : state) {
    benchmark::DoNotOptimize(field->DistanceTrilinear(probes[i], &gradient));
    i = (i + 1) % probes.size();
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_Deskew)->Apply(AllCases);
BENCHMARK(BM_ScanDownsample)->Apply(AllCases);
BENCHMARK(BM_MapUpdate)->Apply(AllCases)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MapEnableDistances)->Apply(AllCases)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BatchDistanceTransform)->Apply(AllCases)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Match)->Apply(AllCases)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TrilinearLookup)->Apply(AllCases);

}  // namespace
}  // namespace unimap::bench

BENCHMARK_MAIN();
