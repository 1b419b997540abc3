#pragma once
// Internal to unimap_io: the binary layout of scans.bin
// (docs/dataset-format.md, "scans.bin"). Little-endian on every host.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/ScanRecord.hpp"

namespace unimap::io {

constexpr char kScanFileMagic[8] = {'U', 'N', 'I', 'M', 'A', 'P', 'S', 'C'};
constexpr std::uint32_t kScanFileVersion = 1;
constexpr std::size_t kScanFileHeaderBytes = 12;   // magic + u32 version
constexpr std::size_t kScanRecordHeaderBytes = 5;  // u8 kind + u32 payload bytes
constexpr std::uint8_t kLineScanKind = 1;
constexpr std::uint8_t kRawScanKind = 2;

// Appends the file header (magic, version).
void AppendScanFileHeader(std::string* out);

// Why a scan cannot be stored (non-finite times, end before start,
// intensities neither empty nor one per beam, too many beams or points for
// one record); empty when it can. Readers apply the same checks.
std::string ScanRecordProblem(const ScanRecord& scan);

// Appends one record: kind, payload size and payload. The scan must have no
// ScanRecordProblem().
void AppendScanRecord(std::string* out, const ScanRecord& scan);

// Little-endian u32 at bytes[0..4).
std::uint32_t LoadU32(const unsigned char* bytes);

// Decodes one record's payload; throws InputError "<where>: <reason>" for an
// unknown kind, a payload whose size does not match its counts, a bad flag
// or a record with a ScanRecordProblem().
ScanRecord DecodeScanPayload(std::uint8_t kind, const unsigned char* payload, std::size_t size,
                             const std::string& where);

}  // namespace unimap::io
