#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "unimap/RawScan.hpp"

namespace unimap::io {

// One field of a sensor_msgs/PointCloud2 (sensor_msgs/PointField), without ROS types.
struct CloudField {
  std::string name;           // "x", "intensity", "time", ...
  std::uint32_t offset = 0;   // byte offset inside a point
  std::uint8_t datatype = 0;  // PointField: 1 INT8 2 UINT8 3 INT16 4 UINT16 5 INT32 6 UINT32 7 FLOAT32 8 FLOAT64
  std::uint32_t count = 1;    // elements (only the first one is read)
};

// How a cloud's points carry their time (docs/real-data.md):
enum class PointTimeConvention {
  kNone,                   // no time field: has_point_time false, every point at the header stamp
  kSecondsAndNanoseconds,  // integer time_sec + time_nsec (absolute)
  kRelativeNanoseconds,    // integer t / offset_time / time (Ouster, Livox): ns after the header stamp
  kRelativeSeconds,        // float time / t / timestamp below 1e6 (Velodyne): s after the header stamp
  kAbsoluteSeconds,        // float time / timestamp in [1e6, 1e15): absolute s (Hesai, Robosense)
  kAbsoluteNanoseconds,    // float timestamp >= 1e15: absolute ns (Livox driver 2)
};

// Name of a convention, for reports ("time_sec+time_nsec (absolute)").
const char* ToString(PointTimeConvention convention);

// A decoded cloud.
struct CloudDecoding {
  RawScan scan;             // points in the cloud's frame; start/end = earliest/latest point time
  std::size_t dropped = 0;  // points with a non-finite x, y or z, or a non-finite time
  PointTimeConvention time_convention = PointTimeConvention::kNone;
};

// Turns PointCloud2 bytes into a RawScan: x y z (required), intensity
// (intensity / reflectivity / i), ring (ring / laser_id / channel / line) and
// a per-point time by the conventions above. Fields are resolved once per
// layout; both byte orders are read.
class PointCloud2Decoder {
 public:
  // Resolves the fields; throws InputError (what = reason) when x, y or z is
  // missing or not a float, or a field does not fit in point_step.
  PointCloud2Decoder(const std::vector<CloudField>& fields, std::uint32_t point_step, bool is_bigendian);

  // Decodes `points` points of `row_step`-sized rows (width points per row);
  // header_stamp_s anchors relative times. Throws InputError when the data is
  // shorter than the layout needs.
  CloudDecoding Decode(const std::uint8_t* data, std::size_t size, std::uint32_t width, std::uint32_t height,
                       std::uint32_t row_step, double header_stamp_s) const;

 private:
  // A resolved field: where it is and how to read it; offset < 0 = absent.
  struct Slot {
    long offset = -1;
    std::uint8_t datatype = 0;
  };
  // Reads the field of the point at p as a double.
  double Read(const Slot& slot, const std::uint8_t* p) const;

  std::uint32_t point_step_;
  bool swap_bytes_;               // the cloud's byte order differs from the host's
  Slot x_, y_, z_;                // coordinates
  Slot intensity_, ring_;         // optional
  Slot time_, time_nsec_;         // per-point time (time_ is time_sec for kSecondsAndNanoseconds)
  bool time_is_integer_ = false;  // integer time field (relative ns) vs float (seconds or ns by magnitude)
  bool sec_nsec_ = false;         // time_sec + time_nsec pair
};

}  // namespace unimap::io
