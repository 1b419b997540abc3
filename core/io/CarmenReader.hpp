#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "unimap/LineScan.hpp"
#include "unimap/OdometrySample.hpp"

namespace unimap::io {

class TextLineSource;

// How FLASER beams are laid out: the log stores only the beam count, so the
// geometry of the SICK LMS class of scanners is assumed (docs/real-data.md).
struct CarmenReaderOptions {
  double fov_rad = 3.14159265358979323846;  // angle the beams span, centred on +x
  double range_min_m = 0.0;                 // shorter returns are invalid
  double range_max_m = 80.0;                // longer returns (SICK max-range marker 81.9x) are invalid
  // A message stamped more than this after the previous one is a clock jump
  // (an InputError naming the line): the real logs step at most 3.5 s (intel.clf).
  double max_time_step_s = 60.0;
  double max_abs_time_s = 1e10;  // |ipc timestamp| (1e10 s: the year 2286 in Unix time)
};

// One FLASER line: "FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_ts host logger_ts".
struct CarmenLaser {
  std::int64_t line = 0;                                   // line number in the log
  LineScan scan;                                           // start_time_s = ipc_ts, time_increment_s = 0 (unknown)
  Eigen::Vector3d pose_xytheta = Eigen::Vector3d::Zero();  // x y theta: the laser pose the logger stored (m, m, rad)
  OdometrySample odometry;                                 // odom_x odom_y odom_theta as a planar pose at ipc_ts
};

// One ODOM line: "ODOM x y theta tv rv accel ipc_ts host logger_ts".
struct CarmenOdometry {
  std::int64_t line = 0;    // line number in the log
  OdometrySample odometry;  // x y theta as a planar pose at ipc_ts
  double tv_m_s = 0.0;      // translational velocity
  double rv_rad_s = 0.0;    // rotational velocity
  double accel_m_s2 = 0.0;  // acceleration
};

// A message the reader delivers.
using CarmenMessage = std::variant<CarmenLaser, CarmenOdometry>;

// A line that was skipped, with why.
struct CarmenSkippedLine {
  std::int64_t line = 0;  // line number in the log
  std::string reason;     // e.g. "truncated last line"
};

// What the reader has seen so far.
struct CarmenReaderStats {
  std::size_t lines = 0;                              // lines read
  std::size_t laser_scans = 0;                        // FLASER lines delivered
  std::size_t odometry = 0;                           // ODOM lines delivered
  std::size_t comments = 0;                           // '#' lines and blank lines
  std::map<std::string, std::size_t> other_messages;  // message type -> lines skipped (PARAM, RLASER, ...)
  std::map<std::string, std::size_t> skipped;         // reason -> lines skipped as damaged
  std::vector<CarmenSkippedLine> skipped_lines;       // the first kMaxListedSkips damaged lines
  bool truncated_input = false;                       // the compressed data ended before its end marker
  static constexpr std::size_t kMaxListedSkips = 20;  // cap of skipped_lines
};

// Streams a CARMEN log (.clf, or bzip2-compressed .clf.bz2), one message at
// a time; memory does not grow with the log. FLASER and ODOM lines are
// delivered; '#' comments and blank lines are counted; other message types
// are counted per type and skipped. A malformed FLASER/ODOM line, or one
// stamped beyond max_abs_time_s or more than max_time_step_s after the
// previous message, throws InputError "<file>:<line>: <reason>" -- except a damaged LAST line (the
// file or its compressed stream ends inside it, as when a logger was killed),
// which is a counted, listed skip (stats().skipped).
class CarmenReader {
 public:
  // Opens the log; throws InputError when it cannot be read.
  explicit CarmenReader(const std::filesystem::path& file, CarmenReaderOptions options = {});
  ~CarmenReader();
  CarmenReader(const CarmenReader&) = delete;
  CarmenReader& operator=(const CarmenReader&) = delete;

  // The next FLASER or ODOM message; std::nullopt at the end of the log.
  std::optional<CarmenMessage> Next();
  const CarmenReaderStats& stats() const { return stats_; }

  // True when the log has at least one ODOM line (reads until the first one).
  static bool HasOdometryLines(const std::filesystem::path& file);
  // Beam layout for n beams over fov_rad centred on +x: even n (180, 360)
  // are n steps of fov/n starting at -fov/2; odd n (181, 361) include both
  // ends, steps of fov/(n-1). Sets angle_min_rad and angle_increment_rad.
  static void SetBeamLayout(std::size_t beams, double fov_rad, LineScan* scan);

 private:
  // Throws FieldError when time_s is beyond the options' clock limits.
  void CheckTime(double time_s) const;
  // Parses a FLASER / ODOM line; throws InputError naming the line.
  CarmenLaser ParseLaser(const std::vector<std::string_view>& fields) const;
  CarmenOdometry ParseOdometry(const std::vector<std::string_view>& fields) const;
  // True when a parse error on the current line is a damaged last line.
  bool AtDamagedEnd() const;

  CarmenReaderOptions options_;
  std::unique_ptr<TextLineSource> source_;  // the log, line by line
  std::string line_;                        // current line text
  std::vector<std::string_view> fields_;    // current line split on blanks
  CarmenReaderStats stats_;
  double last_time_s_ = 0.0;    // ipc timestamp of the previous message delivered
  bool has_last_time_ = false;  // a message was delivered
};

}  // namespace unimap::io
