#pragma once
#include <string>

#include <Eigen/Core>

#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::io {

// Plausibility limits DatasetReader applies while it reads: a value beyond
// them is not a sensor reading (a corrupt file, a unit error), and a time
// step beyond them is a clock jump or lost data, which would otherwise be
// integrated as motion. The reader throws InputError naming the file, the
// line or record and the limit. Sources of the defaults: docs/reliability.md.
struct DatasetLimits {
  // |accelerometer component|: 40 g, the widest full scale among common
  // navigation IMUs (ADIS16470 +-40 g; BMI088 +-24 g, ICM-42686-P +-32 g).
  double max_accel_m_s2 = 40.0 * 9.80665;
  // |gyroscope component|: 4000 deg/s (ICM-42686-P; ADIS16470, BMI088 and
  // Xsens MTi-630 stop at 2000 deg/s).
  double max_gyro_rad_s = 4000.0 * 3.14159265358979323846 / 180.0;
  // |encoder angle| in any wrap convention: a 20 Hz motor (VLP-16 at
  // 1200 rpm) unwrapped for 90 days.
  double max_encoder_angle_rad = 1e9;
  // |x|, |y|, |z| of odometry and ground-truth positions: beyond any
  // Earth-fixed coordinate (ECEF, UTM are below 1e7 m).
  double max_position_m = 1e8;
  // |time|: 1e10 s is the year 2286 as Unix time (catches nanoseconds read as seconds).
  double max_abs_time_s = 1e10;
  // Largest step between consecutive IMU samples: at 100 Hz or more, a
  // second without a sample is lost data or a clock jump, and the filter
  // would integrate across it.
  double max_imu_step_s = 1.0;
  // Largest step between consecutive encoder samples: shorter gaps leave
  // the scans in them uncovered (the localiser skips and counts them).
  double max_encoder_step_s = 10.0;
  // Largest step between consecutive scans / odometry samples (real logs:
  // 3.5 s in the Intel Research Lab CARMEN log).
  double max_scan_step_s = 60.0;
  double max_odometry_step_s = 60.0;
  // Longest scan (end minus start time): a 2D line takes ~25 ms, a 3D sweep
  // 0.05-1 s.
  double max_scan_duration_s = 10.0;
  // Line scans: finite angle_min_rad / angle_increment_rad and
  // 0 <= range_min_m <= range_max_m.
  bool check_line_geometry = true;

  // No limit at all: the dataset format alone (its bit-exact round trip of
  // any double is tested with extreme values).
  static DatasetLimits Unlimited();

  // False (with the reason) when a limit is not positive (NaN included).
  bool IsValid(std::string* why) const;

  // Why a sample is implausible ("accelerometer x 1e+300 m/s^2 is beyond
  // +-392.3 m/s^2"); empty when it is plausible.
  std::string ImuProblem(const ImuSample& sample) const;
  std::string EncoderProblem(const EncoderSample& sample) const;
  std::string PositionProblem(const Eigen::Vector3d& position_m) const;
  std::string ScanProblem(const ScanRecord& scan) const;
};

}  // namespace unimap::io
