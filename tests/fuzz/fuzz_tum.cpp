// libFuzzer harness: a TUM trajectory through ReadTumTrajectory.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    unimap::io::ReadTumTrajectory(scratch.Write("trajectory.tum", data, size));
  } catch (const unimap::Error&) {
  }
  return 0;
}
