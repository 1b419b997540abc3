// libFuzzer harness: a dataset's metadata.yaml through LoadDatasetMetadata.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/DatasetMetadata.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    unimap::io::LoadDatasetMetadata(scratch.Write("metadata.yaml", data, size));
  } catch (const unimap::Error&) {
  }
  return 0;
}
