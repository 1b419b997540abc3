#pragma once
#include <cstdint>

namespace unimap {

// Release of the SDK (matches the CMake project version).
inline constexpr const char* kSdkVersion = "0.1.0";

// Binary interface of PayloadPlugin. Bumped whenever the interface or any
// type crossing it changes layout; the loader refuses plugins built against
// another value (AbiMismatchError).
inline constexpr std::uint32_t kPayloadAbiVersion = 1;

}  // namespace unimap
