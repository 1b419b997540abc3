#include "io/PointCloud2Decoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// PointField datatypes (sensor_msgs/PointField).
constexpr std::uint8_t kInt8 = 1, kUint8 = 2, kInt16 = 3, kUint16 = 4, kInt32 = 5, kUint32 = 6, kFloat32 = 7,
                       kFloat64 = 8;

std::size_t SizeOf(std::uint8_t datatype) {
  switch (datatype) {
    case kInt8:
    case kUint8:
      return 1;
    case kInt16:
    case kUint16:
      return 2;
    case kInt32:
    case kUint32:
    case kFloat32:
      return 4;
    case kFloat64:
      return 8;
    default:
      return 0;
  }
}

bool IsFloat(std::uint8_t datatype) { return datatype == kFloat32 || datatype == kFloat64; }

bool HostIsBigEndian() {
  const std::uint16_t probe = 1;
  std::uint8_t first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 0;
}

// Copies n bytes at p into out, reversed when swap is set.
void LoadBytes(const std::uint8_t* p, std::size_t n, bool swap, void* out) {
  std::uint8_t buffer[8];
  for (std::size_t i = 0; i < n; ++i) buffer[i] = swap ? p[n - 1 - i] : p[i];
  std::memcpy(out, buffer, n);
}

template <typename T>
double LoadAs(const std::uint8_t* p, bool swap) {
  T value;
  LoadBytes(p, sizeof(T), swap, &value);
  return static_cast<double>(value);
}

}  // namespace

const char* ToString(PointTimeConvention convention) {
  switch (convention) {
    case PointTimeConvention::kNone:
      return "none (times derived by the payload plugin)";
    case PointTimeConvention::kSecondsAndNanoseconds:
      return "time_sec + time_nsec (absolute)";
    case PointTimeConvention::kRelativeNanoseconds:
      return "integer ns after the header stamp";
    case PointTimeConvention::kRelativeSeconds:
      return "float s after the header stamp";
    case PointTimeConvention::kAbsoluteSeconds:
      return "float absolute s";
    case PointTimeConvention::kAbsoluteNanoseconds:
      return "float absolute ns";
  }
  return "unknown";
}

PointCloud2Decoder::PointCloud2Decoder(const std::vector<CloudField>& fields, std::uint32_t point_step,
                                       bool is_bigendian)
    : point_step_(point_step), swap_bytes_(is_bigendian != HostIsBigEndian()) {
  // First field among `names` (in that order of preference), checked to fit.
  auto find = [&](std::initializer_list<const char*> names) {
    for (const char* name : names) {
      for (const CloudField& f : fields) {
        if (f.name != name) continue;
        const std::size_t size = SizeOf(f.datatype);
        if (size == 0)
          throw InputError("PointCloud2 field '" + f.name + "' has unknown datatype " + std::to_string(f.datatype));
        if (static_cast<std::size_t>(f.offset) + size > point_step) {
          throw InputError("PointCloud2 field '" + f.name + "' does not fit in point_step " +
                           std::to_string(point_step));
        }
        return Slot{static_cast<long>(f.offset), f.datatype};
      }
    }
    return Slot{};
  };
  x_ = find({"x"});
  y_ = find({"y"});
  z_ = find({"z"});
  for (const Slot* s : {&x_, &y_, &z_}) {
    if (s->offset < 0 || !IsFloat(s->datatype)) throw InputError("PointCloud2 needs float fields x, y and z");
  }
  intensity_ = find({"intensity", "reflectivity", "i"});
  ring_ = find({"ring", "laser_id", "channel", "line"});
  const Slot sec = find({"time_sec"});
  const Slot nsec = find({"time_nsec"});
  if (sec.offset >= 0 && nsec.offset >= 0 && !IsFloat(sec.datatype) && !IsFloat(nsec.datatype)) {
    time_ = sec;
    time_nsec_ = nsec;
    sec_nsec_ = true;
  } else {
    time_ = find({"time", "t", "timestamp", "offset_time"});
    time_is_integer_ = time_.offset >= 0 && !IsFloat(time_.datatype);
  }
}

double PointCloud2Decoder::Read(const Slot& slot, const std::uint8_t* p) const {
  const std::uint8_t* at = p + slot.offset;
  switch (slot.datatype) {
    case kInt8:
      return static_cast<double>(static_cast<std::int8_t>(*at));
    case kUint8:
      return static_cast<double>(*at);
    case kInt16:
      return LoadAs<std::int16_t>(at, swap_bytes_);
    case kUint16:
      return LoadAs<std::uint16_t>(at, swap_bytes_);
    case kInt32:
      return LoadAs<std::int32_t>(at, swap_bytes_);
    case kUint32:
      return LoadAs<std::uint32_t>(at, swap_bytes_);
    case kFloat32:
      return LoadAs<float>(at, swap_bytes_);
    case kFloat64:
      return LoadAs<double>(at, swap_bytes_);
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

CloudDecoding PointCloud2Decoder::Decode(const std::uint8_t* data, std::size_t size, std::uint32_t width,
                                         std::uint32_t height, std::uint32_t row_step, double header_stamp_s) const {
  const std::size_t row_bytes = static_cast<std::size_t>(width) * point_step_;
  if (height > 0 && width > 0 &&
      (row_step < row_bytes || static_cast<std::size_t>(row_step) * (height - 1) + row_bytes > size)) {
    throw InputError("PointCloud2 data (" + std::to_string(size) + " bytes) is shorter than " + std::to_string(width) +
                     "x" + std::to_string(height) + " points of " + std::to_string(point_step_) + " bytes need");
  }
  CloudDecoding out;
  out.scan.points.reserve(static_cast<std::size_t>(width) * height);
  // Per-message choice for float times: absolute or relative, seconds or ns,
  // by the magnitude of the first finite value.
  double scale = 1.0, offset_s = 0.0;
  if (sec_nsec_) {
    out.time_convention = PointTimeConvention::kSecondsAndNanoseconds;
  } else if (time_.offset >= 0 && time_is_integer_) {
    out.time_convention = PointTimeConvention::kRelativeNanoseconds;
    scale = 1e-9;
    offset_s = header_stamp_s;
  } else if (time_.offset >= 0) {
    out.time_convention = PointTimeConvention::kRelativeSeconds;
    offset_s = header_stamp_s;
    for (std::size_t i = 0; i < static_cast<std::size_t>(width) * height; ++i) {
      const std::size_t row = i / width, col = i % width;
      const double v = Read(time_, data + row * row_step + col * point_step_);
      if (!std::isfinite(v)) continue;
      if (std::abs(v) >= 1e15) {
        out.time_convention = PointTimeConvention::kAbsoluteNanoseconds;
        scale = 1e-9;
        offset_s = 0.0;
      } else if (std::abs(v) >= 1e6) {
        out.time_convention = PointTimeConvention::kAbsoluteSeconds;
        offset_s = 0.0;
      }
      break;
    }
  }
  const bool timed = out.time_convention != PointTimeConvention::kNone;
  out.scan.has_point_time = timed;
  double earliest = std::numeric_limits<double>::infinity();
  double latest = -std::numeric_limits<double>::infinity();
  for (std::uint32_t row = 0; row < height; ++row) {
    const std::uint8_t* row_data = data + static_cast<std::size_t>(row) * row_step;
    for (std::uint32_t col = 0; col < width; ++col) {
      const std::uint8_t* p = row_data + static_cast<std::size_t>(col) * point_step_;
      Point point;
      point.position_m = Eigen::Vector3d(Read(x_, p), Read(y_, p), Read(z_, p));
      if (sec_nsec_) {
        point.time_s = Read(time_, p) + 1e-9 * Read(time_nsec_, p);
      } else if (timed) {
        point.time_s = offset_s + scale * Read(time_, p);
      } else {
        point.time_s = header_stamp_s;
      }
      if (!point.position_m.allFinite() || !std::isfinite(point.time_s)) {
        ++out.dropped;
        continue;
      }
      if (intensity_.offset >= 0) point.intensity = static_cast<float>(Read(intensity_, p));
      if (ring_.offset >= 0) {
        point.ring = static_cast<std::uint16_t>(std::clamp(Read(ring_, p), 0.0, 65535.0));
      }
      earliest = std::min(earliest, point.time_s);
      latest = std::max(latest, point.time_s);
      out.scan.points.push_back(point);
    }
  }
  if (out.scan.points.empty() || !timed) {
    out.scan.start_time_s = header_stamp_s;
    out.scan.end_time_s = header_stamp_s;
  } else {
    out.scan.start_time_s = earliest;
    out.scan.end_time_s = latest;
  }
  return out;
}

}  // namespace unimap::io
