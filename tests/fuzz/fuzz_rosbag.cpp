// libFuzzer harness: a ROS 1 bag through RosbagReader (every stream on auto).
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/RosbagReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    unimap::io::RosbagReader reader(scratch.Write("data.bag", data, size));
    while (reader.Next()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
