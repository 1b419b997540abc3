#include "io/RosbagRecords.hpp"

#include <bzlib.h>
#if UNIMAP_WITH_ROSBAG
#include <roslz4/lz4s.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
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
constexpr std::uint8_t kIndexDataOp = 0x04;
constexpr std::uint8_t kChunkOp = 0x05;
constexpr std::uint8_t kChunkInfoOp = 0x06;
constexpr std::uint8_t kConnectionOp = 0x07;       // its data is a header too (topic, type, md5sum, definition)
constexpr std::uint64_t kIndexEntryBytes = 12;     // u32 secs, u32 nsecs, u32 offset into the chunk
constexpr std::uint64_t kChunkInfoEntryBytes = 8;  // u32 connection, u32 its message count

std::uint32_t U32(const unsigned char* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

std::uint64_t U64(const unsigned char* bytes) {
  return static_cast<std::uint64_t>(U32(bytes)) | static_cast<std::uint64_t>(U32(bytes + 4)) << 32;
}

// What CheckRosbagRecords needs of a record's header.
struct RecordHeader {
  std::uint8_t op = 0;
  std::string compression;  // a chunk's
  bool has_size = false;    // a chunk's uncompressed size
  std::uint64_t size = 0;
  bool has_position = false;  // index_pos (bag header) or chunk_pos (chunk info)
  std::uint64_t position = 0;
  bool has_count = false;  // entries of index data, connections of a chunk info
  std::uint64_t count = 0;
};

// Parses the fields (u32 length, "name=value") of a header of n bytes.
RecordHeader ParseHeader(const unsigned char* h, std::uint64_t n, const std::string& where) {
  RecordHeader out;
  for (std::uint64_t f = 0; f < n;) {
    if (n - f < 4) throw InputError(where + "a header field is cut");
    const std::uint64_t field_bytes = U32(&h[f]);
    if (field_bytes > n - f - 4) throw InputError(where + "a header field runs past its header");
    const std::string field(reinterpret_cast<const char*>(&h[f + 4]), field_bytes);
    const std::size_t equals = field.find('=');
    if (equals == std::string::npos) throw InputError(where + "a header field has no '='");
    const std::string key = field.substr(0, equals), value = field.substr(equals + 1);
    const auto* v = reinterpret_cast<const unsigned char*>(value.data());
    if (key == "op" && value.size() == 1) out.op = v[0];
    if (key == "compression") out.compression = value;
    if (key == "size" && value.size() == 4) {
      out.size = U32(v);
      out.has_size = true;
    }
    if (key == "count" && value.size() == 4) {
      out.count = U32(v);
      out.has_count = true;
    }
    if ((key == "index_pos" || key == "chunk_pos") && value.size() == 8) {
      out.position = U64(v);
      out.has_position = true;
    }
    f += 4 + field_bytes;
  }
  return out;
}

// The records inside a chunk's uncompressed data, walked as the file's are:
// returns their starts (the offsets its index data may name).
std::vector<std::uint64_t> WalkChunk(const unsigned char* data, std::uint64_t size, const std::string& where) {
  std::vector<std::uint64_t> starts;
  for (std::uint64_t at = 0; at < size;) {
    const std::string inner = where + "the chunk's record at offset " + std::to_string(at) + ": ";
    if (size - at < 4) throw InputError(inner + "truncated length");
    const std::uint64_t header_bytes = U32(&data[at]);
    if (header_bytes > size - at - 4) throw InputError(inner + "a header running past the chunk");
    const RecordHeader fields = ParseHeader(&data[at + 4], header_bytes, inner);
    if (size - at - 4 - header_bytes < 4) throw InputError(inner + "truncated data length");
    const std::uint64_t data_bytes = U32(&data[at + 4 + header_bytes]);
    if (data_bytes > size - at - 8 - header_bytes) throw InputError(inner + "data running past the chunk");
    if (fields.op == kConnectionOp) ParseHeader(&data[at + 8 + header_bytes], data_bytes, inner + "its connection: ");
    starts.push_back(at);
    at += 8 + header_bytes + data_bytes;
  }
  return starts;
}

// A compressed chunk's data uncompressed to its announced size, into a
// buffer left uninitialised: its pages are touched only as bytes arrive, so
// a damaged header announcing up to kMaxChunkBytes costs what the data
// really holds, not a zeroed gigabyte.
std::unique_ptr<unsigned char[]> Uncompress(std::vector<unsigned char> data, const RecordHeader& chunk,
                                            const std::string& where) {
  std::unique_ptr<unsigned char[]> out(new unsigned char[chunk.size]);
  unsigned int out_bytes = static_cast<unsigned int>(chunk.size);
  int ok = 0;
  if (chunk.compression == "bz2") {
    ok =
        BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(out.get()), &out_bytes, reinterpret_cast<char*>(data.data()),
                                   static_cast<unsigned int>(data.size()), 0, 0) == BZ_OK;
#if UNIMAP_WITH_ROSBAG
  } else if (chunk.compression == "lz4") {
    ok = roslz4_buffToBuffDecompress(reinterpret_cast<char*>(data.data()), static_cast<unsigned int>(data.size()),
                                     reinterpret_cast<char*>(out.get()), &out_bytes) == ROSLZ4_OK;
#endif
  } else {
    throw InputError(where + "a chunk compressed as \"" + chunk.compression + "\" (none, bz2 and lz4 are read)");
  }
  if (!ok || out_bytes != chunk.size) {
    throw InputError(where + "a " + chunk.compression + " chunk that does not uncompress to its " +
                     std::to_string(chunk.size) + " bytes");
  }
  return out;
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
  std::vector<unsigned char> header, data;
  std::vector<std::uint64_t> starts, chunk_starts;  // of the records walked (ascending)
  std::vector<std::uint64_t> chunk_records;         // the records inside the last chunk (offsets)
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
    const RecordHeader fields = ParseHeader(header.data(), header_bytes, where);
    if (size - at - 4 - header_bytes < 4 || !in.read(reinterpret_cast<char*>(length), 4)) {
      throw InputError(where + "truncated data length");
    }
    const std::uint64_t data_bytes = U32(length);
    const std::uint64_t left = size - at - 8 - header_bytes;
    if (data_bytes > left) {
      throw InputError(where + "data of " + std::to_string(data_bytes) + " bytes, " + std::to_string(left) +
                       " bytes left in the file");
    }
    // librosbag reads an index data's and a chunk info's `count` entries
    // from the file, wherever they end: past the record's data, the next
    // "record" it reads is arbitrary bytes.
    if (fields.op == kIndexDataOp || fields.op == kChunkInfoOp) {
      const std::uint64_t entry = fields.op == kIndexDataOp ? kIndexEntryBytes : kChunkInfoEntryBytes;
      if (!fields.has_count || fields.count * entry != data_bytes) {
        throw InputError(where + (fields.op == kIndexDataOp ? "index data" : "a chunk info") + " announcing " +
                         (fields.has_count ? std::to_string(fields.count) : std::string("no")) + " entries of " +
                         std::to_string(entry) + " bytes in " + std::to_string(data_bytes) + " bytes of data");
      }
    }
    const bool chunk = fields.op == kChunkOp;
    if (chunk && fields.has_size &&
        (fields.size > kMaxChunkBytes || (fields.compression == "none" && fields.size != data_bytes))) {
      throw InputError(where + "a chunk announcing " + std::to_string(fields.size) + " bytes uncompressed from " +
                       std::to_string(data_bytes) + " bytes of data");
    }
    if (chunk || fields.op == kIndexDataOp || fields.op == kConnectionOp) {
      // librosbag parses what these hold with lengths as unchecked as the
      // file's: the records inside a chunk (where its index data says they
      // start) and the header that is a connection record's data.
      data.resize(data_bytes);
      in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data_bytes));
      if (fields.op == kConnectionOp) {
        ParseHeader(data.data(), data_bytes, where + "its connection: ");
      } else if (chunk) {
        if (!fields.has_size) throw InputError(where + "a chunk without its uncompressed size");
        if (fields.compression == "none") {
          chunk_records = WalkChunk(data.data(), data.size(), where);
        } else {
          const std::unique_ptr<unsigned char[]> uncompressed = Uncompress(std::move(data), fields, where);
          chunk_records = WalkChunk(uncompressed.get(), fields.size, where);
        }
        chunk_starts.push_back(at);
      } else {
        for (std::uint64_t e = 0; e < data_bytes; e += kIndexEntryBytes) {
          const std::uint32_t offset = U32(&data[e + 8]);
          if (!std::binary_search(chunk_records.begin(), chunk_records.end(), offset)) {
            throw InputError(where + "index data naming offset " + std::to_string(offset) +
                             ", not the start of a record in the chunk before it");
          }
        }
      }
    } else {
      in.seekg(static_cast<std::streamoff>(data_bytes), std::ios::cur);
    }
    // A bag header's index_pos of 0 marks a bag never indexed (librosbag says so).
    if (fields.has_position && fields.op == kBagHeaderOp && fields.position != 0) {
      pointers.push_back({at, fields.position, false, "index_pos"});
    }
    if (fields.has_position && fields.op == kChunkInfoOp) pointers.push_back({at, fields.position, true, "chunk_pos"});
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
