// libFuzzer harness: ROS 1 message definitions and messages read by them
// (Ros1MessageDefinition, what RosbagReader uses for custom messages). The
// input is a definition text, a NUL byte, then a serialized message; the
// message is searched for a LaserScan and its fields are located and read.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/Ros1MessageDefinition.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
  if (nul == nullptr) return 0;
  const std::string text(reinterpret_cast<const char*>(data), static_cast<std::size_t>(nul - data));
  const std::uint8_t* message = nul + 1;
  const std::size_t length = size - static_cast<std::size_t>(nul - data) - 1;
  try {
    const unimap::io::Ros1MessageDefinition d("fuzz/Message", text);
    for (const std::string& path : d.FieldsOfType("sensor_msgs/LaserScan")) {
      d.Locate(message, length, path);
      d.ReadNumber(message, length, path + ".range_max");
    }
    for (const char* path : {"", "data", "stepAngle", "header.stamp", "laserScan.header.seq"}) {
      try {
        d.Locate(message, length, path);
        d.ReadNumber(message, length, path);
      } catch (const unimap::Error&) {
      }
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
