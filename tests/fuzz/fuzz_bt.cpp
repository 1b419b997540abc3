// libFuzzer harness: an OctoMap .bt prior map through DistanceMap::LoadBt
// (what `unimap localize --map MAP.bt` does), with a small distance box:
// the tree's reading and checks are what is fuzzed; a 1 m range and at most
// 30,000 distance cells made 179 executions/s against 115 with 2 m and
// 200,000 (most of the rest is reading the tree). Trees whose occupied
// leaves cover up to the default 10^7 voxels took seconds each to expand
// (the run fell to 54 executions/s): the harness's cap is 10^5.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "map/DistanceMap.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  unimap::map::DistanceMapOptions options;
  options.max_range_m = 1.0;
  options.max_edt_cells = 30000;
  options.max_occupied_voxels = 100000;
  try {
    auto map = unimap::map::DistanceMap::LoadBt(scratch.Write("map.bt", data, size), options, Eigen::Vector3f::Zero());
    map->WaitForUpdates();
  } catch (const unimap::Error&) {
  }
  return 0;
}
