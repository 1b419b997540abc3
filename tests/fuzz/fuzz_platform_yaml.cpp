// libFuzzer harness: a platform file (YAML) through PlatformFile::Parse.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/PlatformFile.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    unimap::PlatformFile::Parse(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const unimap::ConfigError&) {
  }
  return 0;
}
