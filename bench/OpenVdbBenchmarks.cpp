// The third distance-map candidate issue 20 names (docs/mapping.md,
// "Distance map candidates"): OpenVDB's sparse grids (Debian's
// libopenvdb-dev 10), built only when it is installed. Each key scan's
// voxels are rasterised as spheres into a narrow-band level set
// (tools::ParticlesToLevelSet), the way OpenVDB turns points into a distance
// field, with the band as wide as the map's clamp; one thread (the
// benchmarks run pinned to one core).
#include <benchmark/benchmark.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <tbb/global_control.h>

#include <cmath>
#include <vector>

#include "BenchCases.hpp"

namespace unimap::bench {
namespace {

// Spheres for ParticlesToLevelSet: every point with one radius.
struct Spheres {
  using PosType = openvdb::Vec3R;
  std::vector<openvdb::Vec3R> centres;
  openvdb::Real radius = 0.0;
  std::size_t size() const { return centres.size(); }
  void getPos(std::size_t n, openvdb::Vec3R& p) const { p = centres[n]; }
  void getPosRad(std::size_t n, openvdb::Vec3R& p, openvdb::Real& r) const {
    p = centres[n];
    r = radius;
  }
};

// Every key scan rasterised into one growing level set (voxel = the map's,
// band = its clamp, spheres of the smallest radius ParticlesToLevelSet
// keeps: 1.5 voxels), finalised after each as the map must be queryable
// then; items are key scans. Counters: active voxels at the end, bytes.
void BM_OpenVdbLevelSetPerKeyScan(benchmark::State& state) {
  const StageInputs& in = CaseInputs(state);
  state.SetLabel(in.name);
  openvdb::initialize();
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const double voxel = in.options.map.resolution_m;
  const double half_width = std::ceil(in.options.map.clamp_distance_m / voxel);
  std::vector<Spheres> keys(in.key_scans.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    keys[k].radius = 1.5 * voxel;
    for (const Eigen::Vector3f& p : in.key_scans[k].points_map) keys[k].centres.emplace_back(p.x(), p.y(), p.z());
  }
  openvdb::Index64 active = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, half_width);
    for (const Spheres& key : keys) {
      openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
      raster.setRmin(1.5);
      raster.rasterizeSpheres(key);
      raster.finalize(true);
    }
    active = grid->activeVoxelCount();
    bytes = grid->memUsage();
    benchmark::DoNotOptimize(grid);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(keys.size()));
  state.counters["active_voxels"] = static_cast<double>(active);
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}

BENCHMARK(BM_OpenVdbLevelSetPerKeyScan)->Apply(AllCases)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace unimap::bench
