// libFuzzer harness: a dataset's scans.bin through DatasetReader.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  scratch.Write("metadata.yaml", "format_version: 1\npayload: rotating_2d\n");
  scratch.Write("scans.bin", data, size);
  try {
    unimap::io::DatasetReader reader(scratch.folder());
    while (reader.NextScan()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
