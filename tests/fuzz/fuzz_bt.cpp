// libFuzzer harness: an OctoMap .bt prior map through DistanceMap::LoadBt
// (what `unimap localize --map MAP.bt` does), with a small distance box.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "map/DistanceMap.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  unimap::map::DistanceMapOptions options;
  options.max_range_m = 2.0;
  options.max_edt_cells = 200000;
  try {
    auto map = unimap::map::DistanceMap::LoadBt(scratch.Write("map.bt", data, size), options, Eigen::Vector3f::Zero());
    map->WaitForUpdates();
  } catch (const unimap::Error&) {
  }
  return 0;
}
