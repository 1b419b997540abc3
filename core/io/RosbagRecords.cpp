#include "io/RosbagRecords.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;  // real headers: tens of bytes to a few KiB
constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{1} << 30;   // ROS writes 768 KiB chunks by default
constexpr std::uint8_t kBagHeaderOp = 0x03;
constexpr std::uint8_t kChunkOp = 0x05;
constexpr std::uint8_t kChunkInfoOp = 0x06;

std::uint32_t U32(const unsigned char* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

std::uint64_t U64(const unsigned char* bytes) {
  return static_cast<std::uint64_t>(U32(bytes)) | static_cast<std::uint64_t>(U32(bytes + 4)) << 32;
}

// A position another record points to (librosbag seeks there and reads a record).
struct Pointer {
  std::uint64_t from;  // the pointing record's start
  std::uint64_t to;    // where it points
  bool to_chunk;       // must be a chunk (a chunk info's chunk_pos), else any record (index_pos)
  const char* field;   // its name, for the error
};

}  // namespace

void CheckRosbagRecords(const std::filesystem::path& bag) {
  const std::string name = bag.string();
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(bag, ec);
  if (ec) throw InputError(name + ": cannot read: " + ec.message());
  std::ifstream in(bag, std::ios::binary);
  char magic[sizeof(kMagic) - 1];
  if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kMagic, sizeof(magic)) != 0) {
    throw InputError(name + ": cannot read ROS bag: not a ROS bag of format 2.0 (no \"#ROSBAG V2.0\" line)");
  }
  std::uint64_t at = sizeof(magic);
  std::vector<unsigned char> header;
  std::vector<std::uint64_t> starts, chunk_starts;  // of the records walked (ascending)
  std::vector<Pointer> pointers;
  while (at < size) {
    starts.push_back(at);
    const std::string where = name + ": cannot read ROS bag: record at byte " + std::to_string(at) + ": ";
    unsigned char length[4];
    if (size - at < 4 || !in.read(reinterpret_cast<char*>(length), 4)) throw InputError(where + "truncated length");
    const std::uint64_t header_bytes = U32(length);
    if (header_bytes > size - at - 4 || header_bytes > kMaxHeaderBytes) {
      throw InputError(where + "a header of " + std::to_string(header_bytes) + " bytes, " +
                       std::to_string(size - at - 4) + " bytes left in the file");
    }
    header.resize(header_bytes);
    in.read(reinterpret_cast<char*>(header.data()), static_cast<std::streamsize>(header_bytes));
    std::uint64_t chunk_size = 0;
    bool chunk = false, uncompressed = false, has_size = false;
    std::uint8_t op = 0;
    std::uint64_t position = 0;
    bool has_position = false;
    for (std::uint64_t f = 0; f < header_bytes;) {
      if (header_bytes - f < 4) throw InputError(where + "a header field is cut");
      const std::uint64_t field_bytes = U32(&header[f]);
      if (field_bytes > header_bytes - f - 4) throw InputError(where + "a header field runs past its header");
      const std::string field(reinterpret_cast<const char*>(&header[f + 4]), field_bytes);
      const std::size_t equals = field.find('=');
      if (equals == std::string::npos) throw InputError(where + "a header field has no '='");
      const std::string key = field.substr(0, equals), value = field.substr(equals + 1);
      if (key == "op" && value.size() == 1) {
        op = static_cast<std::uint8_t>(value[0]);
        chunk = op == kChunkOp;
      }
      if ((key == "index_pos" || key == "chunk_pos") && value.size() == 8) {
        position = U64(reinterpret_cast<const unsigned char*>(value.data()));
        has_position = true;
      }
      if (key == "compression") uncompressed = value == "none";
      if (key == "size" && value.size() == 4) {
        chunk_size = U32(reinterpret_cast<const unsigned char*>(value.data()));
        has_size = true;
      }
      f += 4 + field_bytes;
    }
    if (size - at - 4 - header_bytes < 4 || !in.read(reinterpret_cast<char*>(length), 4)) {
      throw InputError(where + "truncated data length");
    }
    const std::uint64_t data_bytes = U32(length);
    const std::uint64_t left = size - at - 8 - header_bytes;
    if (data_bytes > left) {
      throw InputError(where + "data of " + std::to_string(data_bytes) + " bytes, " + std::to_string(left) +
                       " bytes left in the file");
    }
    if (chunk && has_size && (chunk_size > kMaxChunkBytes || (uncompressed && chunk_size != data_bytes))) {
      throw InputError(where + "a chunk announcing " + std::to_string(chunk_size) + " bytes uncompressed from " +
                       std::to_string(data_bytes) + " bytes of data");
    }
    if (chunk) chunk_starts.push_back(at);
    // A bag header's index_pos of 0 marks a bag never indexed (librosbag says so).
    if (has_position && op == kBagHeaderOp && position != 0) pointers.push_back({at, position, false, "index_pos"});
    if (has_position && op == kChunkInfoOp) pointers.push_back({at, position, true, "chunk_pos"});
    in.seekg(static_cast<std::streamoff>(data_bytes), std::ios::cur);
    at += 8 + header_bytes + data_bytes;
  }
  // librosbag reads a record wherever these point: each must be one of the
  // records walked (a length read elsewhere is arbitrary bytes).
  for (const Pointer& p : pointers) {
    const std::vector<std::uint64_t>& targets = p.to_chunk ? chunk_starts : starts;
    if (!std::binary_search(targets.begin(), targets.end(), p.to)) {
      throw InputError(name + ": cannot read ROS bag: record at byte " + std::to_string(p.from) + ": its " + p.field +
                       " " + std::to_string(p.to) + " is not the start of a " + (p.to_chunk ? "chunk" : "record"));
    }
  }
}

}  // namespace unimap::io
