// libFuzzer harness: a dataset's text streams (imu.csv, encoder.csv,
// odometry.csv, groundtruth.tum) through DatasetReader. The first byte picks
// the stream, the rest is the file.
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kStreams[] = {"imu.csv", "encoder.csv", "odometry.csv", "groundtruth.tum"};
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  for (const char* name : kStreams) scratch.Remove(name);
  scratch.Write("metadata.yaml", "format_version: 1\npayload: rotating_2d\n");
  const char* stream = kStreams[data[0] % 4];
  scratch.Write(stream, data + 1, size - 1);
  try {
    unimap::io::DatasetReader reader(scratch.folder());
    while (reader.NextEvent()) {
    }
    while (reader.NextGroundTruth()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
