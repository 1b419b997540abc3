#include "io/ScanCodec.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kLineFixedBytes = 6 * 8 + 4 + 4;  // header doubles, n, m
constexpr std::size_t kRawFixedBytes = 8 + 8 + 1 + 4;   // start, end, flag, n
constexpr std::size_t kRawPointBytes = 4 * 8 + 4 + 2;   // x y z time, intensity, ring
constexpr std::size_t kMaxPayloadBytes = std::numeric_limits<std::uint32_t>::max();

// Appends little-endian integers and IEEE-754 bit patterns.
struct ByteSink {
  std::string* out;
  void U8(std::uint8_t v) { out->push_back(static_cast<char>(v)); }
  void U16(std::uint16_t v) {
    for (int i = 0; i < 2; ++i) U8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void U32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) U8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void U64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) U8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void F32(float v) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof(bits));
    U32(bits);
  }
  void F64(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof(bits));
    U64(bits);
  }
};

// Reads what ByteSink wrote; the caller checks the sizes beforehand.
struct ByteSource {
  const unsigned char* at;
  std::uint64_t Le(int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{at[i]} << (8 * i);
    at += bytes;
    return v;
  }
  std::uint8_t U8() { return static_cast<std::uint8_t>(Le(1)); }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Le(2)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(Le(4)); }
  float F32() {
    const std::uint32_t bits = U32();
    float v = 0.0f;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
  }
  double F64() {
    const std::uint64_t bits = Le(8);
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
  }
};

std::size_t LinePayloadBytes(const LineScan& line) {
  return kLineFixedBytes + 4 * (line.ranges_m.size() + line.intensities.size());
}

std::size_t RawPayloadBytes(const RawScan& raw) { return kRawFixedBytes + kRawPointBytes * raw.points.size(); }

std::string LineProblem(const LineScan& line) {
  if (!std::isfinite(line.start_time_s) || !std::isfinite(line.time_increment_s)) {
    return "line scan start_time_s and time_increment_s must be finite";
  }
  if (!line.intensities.empty() && line.intensities.size() != line.ranges_m.size()) {
    return "line scan has " + std::to_string(line.intensities.size()) + " intensities for " +
           std::to_string(line.ranges_m.size()) + " beams (give none or one per beam)";
  }
  if (line.ranges_m.size() > kMaxPayloadBytes / 8) return "line scan has too many beams";
  return {};
}

std::string RawProblem(const RawScan& raw) {
  if (!std::isfinite(raw.start_time_s) || !std::isfinite(raw.end_time_s)) {
    return "raw scan start_time_s and end_time_s must be finite";
  }
  if (raw.end_time_s < raw.start_time_s) return "raw scan ends before it starts";
  if (raw.points.size() > (kMaxPayloadBytes - kRawFixedBytes) / kRawPointBytes) {
    return "raw scan has too many points for one record";
  }
  return {};
}

LineScan DecodeLine(const unsigned char* payload, std::size_t size, const std::string& where) {
  if (size < kLineFixedBytes) {
    throw InputError(where + ": LineScan payload of " + std::to_string(size) +
                     " bytes is shorter than its fixed fields");
  }
  ByteSource in{payload};
  LineScan line;
  line.start_time_s = in.F64();
  line.angle_min_rad = in.F64();
  line.angle_increment_rad = in.F64();
  line.time_increment_s = in.F64();
  line.range_min_m = in.F64();
  line.range_max_m = in.F64();
  const std::size_t n = in.U32();
  if (size < kLineFixedBytes + 4 * n) {
    throw InputError(where + ": LineScan payload of " + std::to_string(size) + " bytes cannot hold its " +
                     std::to_string(n) + " ranges");
  }
  line.ranges_m.resize(n);
  for (float& range : line.ranges_m) range = in.F32();
  const std::size_t m = in.U32();
  if (m != 0 && m != n) {
    throw InputError(where + ": LineScan has " + std::to_string(m) + " intensities for " + std::to_string(n) +
                     " beams");
  }
  if (size != kLineFixedBytes + 4 * (n + m)) {
    throw InputError(where + ": LineScan payload is " + std::to_string(size) + " bytes, its counts say " +
                     std::to_string(kLineFixedBytes + 4 * (n + m)));
  }
  line.intensities.resize(m);
  for (float& intensity : line.intensities) intensity = in.F32();
  return line;
}

RawScan DecodeRaw(const unsigned char* payload, std::size_t size, const std::string& where) {
  if (size < kRawFixedBytes) {
    throw InputError(where + ": RawScan payload of " + std::to_string(size) +
                     " bytes is shorter than its fixed fields");
  }
  ByteSource in{payload};
  RawScan raw;
  raw.start_time_s = in.F64();
  raw.end_time_s = in.F64();
  const std::uint8_t flag = in.U8();
  if (flag > 1) {
    throw InputError(where + ": RawScan has_point_time is " + std::to_string(flag) + ", expected 0 or 1");
  }
  raw.has_point_time = flag == 1;
  const std::size_t n = in.U32();
  if (size != kRawFixedBytes + kRawPointBytes * n) {
    throw InputError(where + ": RawScan payload is " + std::to_string(size) + " bytes, its point count says " +
                     std::to_string(kRawFixedBytes + kRawPointBytes * n));
  }
  raw.points.resize(n);
  for (Point& point : raw.points) {
    point.position_m.x() = in.F64();
    point.position_m.y() = in.F64();
    point.position_m.z() = in.F64();
    point.time_s = in.F64();
    point.intensity = in.F32();
    point.ring = in.U16();
  }
  return raw;
}

}  // namespace

void AppendScanFileHeader(std::string* out) {
  out->append(kScanFileMagic, sizeof(kScanFileMagic));
  ByteSink{out}.U32(kScanFileVersion);
}

std::string ScanRecordProblem(const ScanRecord& scan) {
  if (const auto* line = std::get_if<LineScan>(&scan)) return LineProblem(*line);
  return RawProblem(std::get<RawScan>(scan));
}

void AppendScanRecord(std::string* out, const ScanRecord& scan) {
  ByteSink sink{out};
  if (const auto* line = std::get_if<LineScan>(&scan)) {
    out->reserve(out->size() + kScanRecordHeaderBytes + LinePayloadBytes(*line));
    sink.U8(kLineScanKind);
    sink.U32(static_cast<std::uint32_t>(LinePayloadBytes(*line)));
    sink.F64(line->start_time_s);
    sink.F64(line->angle_min_rad);
    sink.F64(line->angle_increment_rad);
    sink.F64(line->time_increment_s);
    sink.F64(line->range_min_m);
    sink.F64(line->range_max_m);
    sink.U32(static_cast<std::uint32_t>(line->ranges_m.size()));
    for (const float range : line->ranges_m) sink.F32(range);
    sink.U32(static_cast<std::uint32_t>(line->intensities.size()));
    for (const float intensity : line->intensities) sink.F32(intensity);
    return;
  }
  const RawScan& raw = std::get<RawScan>(scan);
  out->reserve(out->size() + kScanRecordHeaderBytes + RawPayloadBytes(raw));
  sink.U8(kRawScanKind);
  sink.U32(static_cast<std::uint32_t>(RawPayloadBytes(raw)));
  sink.F64(raw.start_time_s);
  sink.F64(raw.end_time_s);
  sink.U8(raw.has_point_time ? 1 : 0);
  sink.U32(static_cast<std::uint32_t>(raw.points.size()));
  for (const Point& point : raw.points) {
    sink.F64(point.position_m.x());
    sink.F64(point.position_m.y());
    sink.F64(point.position_m.z());
    sink.F64(point.time_s);
    sink.F32(point.intensity);
    sink.U16(point.ring);
  }
}

std::uint32_t LoadU32(const unsigned char* bytes) { return ByteSource{bytes}.U32(); }

ScanRecord DecodeScanPayload(std::uint8_t kind, const unsigned char* payload, std::size_t size,
                             const std::string& where) {
  ScanRecord scan;
  if (kind == kLineScanKind) {
    scan = DecodeLine(payload, size, where);
  } else if (kind == kRawScanKind) {
    scan = DecodeRaw(payload, size, where);
  } else {
    throw InputError(where + ": unknown record kind " + std::to_string(kind) +
                     " (expected 1 = LineScan or 2 = RawScan)");
  }
  const std::string problem = ScanRecordProblem(scan);
  if (!problem.empty()) throw InputError(where + ": " + problem);
  return scan;
}

}  // namespace unimap::io
