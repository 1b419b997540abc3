// libFuzzer harness: a CARMEN log (plain or bzip2) through CarmenReader.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/CarmenReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    const auto file = scratch.Write("log.clf", data, size);
    unimap::io::CarmenReader::HasOdometryLines(file);
    unimap::io::CarmenReader reader(file);
    while (reader.Next()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
