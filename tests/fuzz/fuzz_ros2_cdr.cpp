// libFuzzer harness: ROS 2 messages (CDR) through the decoders Ros2BagReader
// uses. The first byte picks the message type, the rest is the serialized
// message; the decoded cloud also goes through PointCloud2Decoder.
#include <cstddef>
#include <cstdint>
#include <exception>

#include "io/CdrMessages.hpp"
#include "unimap/Errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  namespace io = unimap::io;
  const std::uint8_t* message = data + 1;
  const std::size_t length = size - 1;
  try {
    switch (data[0] % 9) {
      case 0:
        io::DecodeLaserScan(message, length);
        break;
      case 1:
        io::DecodeImu(message, length);
        break;
      case 2:
        io::DecodeJointState(message, length);
        break;
      case 3:
        io::DecodePoseStamped(message, length);
        break;
      case 4:
        io::DecodeOdometry(message, length);
        break;
      case 5:
        io::DecodePointCloud2(message, length);
        break;
      case 6:
        io::DecodeScalar(io::CdrScalar::kFloat32, message, length);
        break;
      case 7:
        io::DecodeScalar(io::CdrScalar::kFloat64, message, length);
        break;
      default:
        io::DecodeScalar(io::CdrScalar::kInt32, message, length);
        break;
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
