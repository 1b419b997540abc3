#pragma once
// Checks on PNG bytes: the 8-byte signature and the IHDR chunk's size.
#include <cstdint>
#include <string>

namespace unimap::eval::testing {

// True when bytes start with the PNG signature followed by an IHDR chunk.
inline bool HasPngSignatureAndIhdr(const std::string& bytes) {
  static const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
  return bytes.size() >= 33 && bytes.compare(0, 8, kSignature) == 0 && bytes.compare(12, 4, "IHDR") == 0;
}

// Big-endian 32-bit value at offset.
inline std::uint32_t ReadBigEndian32(const std::string& bytes, std::size_t offset) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[offset + i]);
  return v;
}

// IHDR width and height (bytes 16..23).
inline std::uint32_t PngWidth(const std::string& bytes) { return ReadBigEndian32(bytes, 16); }
inline std::uint32_t PngHeight(const std::string& bytes) { return ReadBigEndian32(bytes, 20); }

}  // namespace unimap::eval::testing
