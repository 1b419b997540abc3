// libFuzzer harness: a PCD point cloud through LoadPcdXyzi.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "FuzzScratch.hpp"
#include "io/PcdPointLoader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  std::vector<Eigen::Vector4f> xyzi;
  try {
    unimap::io::LoadPcdXyzi(scratch.Write("cloud.pcd", data, size), &xyzi);
  } catch (const unimap::Error&) {
  }
  return 0;
}
