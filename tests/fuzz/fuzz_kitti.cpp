// libFuzzer harness: a KITTI sequence folder through KittiReader: the first
// byte picks what the input is (a .bin scan, a .pcd scan, times.txt,
// calib.txt or poses.txt beside a one-point .bin scan).
#include <cstddef>
#include <cstdint>

#include "FuzzScratch.hpp"
#include "io/KittiReader.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kFiles[] = {"000000.bin", "000000.pcd", "times.txt", "calib.txt", "poses.txt"};
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  for (const char* name : kFiles) scratch.Remove(name);
  const int kind = data[0] % 5;
  if (kind >= 2) scratch.Write("000000.bin", std::string(16, '\0'));
  scratch.Write(kFiles[kind], data + 1, size - 1);
  try {
    unimap::io::KittiReader reader(scratch.folder());
    while (reader.Next()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
