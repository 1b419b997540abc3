// libFuzzer harness: a PLY point cloud through ReadPlyVertices.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/PlyReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    unimap::io::ReadPlyVertices(scratch.Write("map.ply", data, size));
  } catch (const unimap::Error&) {
  }
  return 0;
}
