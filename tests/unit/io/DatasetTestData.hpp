#pragma once
// Deterministic dataset contents for the DatasetWriter / DatasetReader tests
// and bit-exact comparisons of what comes back.
#include <limits>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "IoTestSupport.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io::test {

// Rounding bound for a rotation matrix that went through the file's
// quaternion (R -> q -> exact text -> q -> normalise -> R): every step is a
// few floating-point operations on values <= 1, so entries and R^T R - I are
// off by a few ulps of 1 (1e6 random rotations: at most 7 and 12 eps).
constexpr double kRotationRoundTrip = 16 * std::numeric_limits<double>::epsilon();

inline Eigen::Isometry3d RandomPose(ValueSource& v) {
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(v.Uniform(-1, 1), v.Uniform(-1, 1), v.Uniform(-1, 1), v.Uniform(-1, 1)).normalized();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = Eigen::Vector3d(v.Finite(), v.Finite(), v.Finite());
  return T;
}

inline ImuSample RandomImu(ValueSource& v, double time_s) {
  ImuSample s;
  s.time_s = time_s;
  s.accel_m_s2 = Eigen::Vector3d(v.Any(), v.Any(), v.Any());
  s.gyro_rad_s = Eigen::Vector3d(v.Any(), v.Any(), v.Any());
  return s;
}

inline LineScan RandomLine(ValueSource& v, double start_time_s, int beams) {
  LineScan line;
  line.start_time_s = start_time_s;
  line.angle_min_rad = v.Any();
  line.angle_increment_rad = v.Any();
  line.time_increment_s = 1e-5;
  line.range_min_m = v.Any();
  line.range_max_m = v.Any();
  for (int i = 0; i < beams; ++i) line.ranges_m.push_back(v.AnyFloat());
  if (beams % 2 == 0) {
    for (int i = 0; i < beams; ++i) line.intensities.push_back(v.AnyFloat());
  }
  return line;
}

inline RawScan RandomRaw(ValueSource& v, double start_time_s, int points) {
  RawScan raw;
  raw.start_time_s = start_time_s;
  raw.end_time_s = start_time_s + 0.1;
  raw.has_point_time = points % 2 == 0;
  for (int i = 0; i < points; ++i) {
    Point p;
    p.position_m = Eigen::Vector3d(v.Any(), v.Any(), v.Any());
    p.time_s = v.Any();
    p.intensity = v.AnyFloat();
    p.ring = static_cast<std::uint16_t>(v.Int(0, 65535));
    raw.points.push_back(p);
  }
  return raw;
}

inline void ExpectSameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(SameBits(a[i], b[i])) << a[i] << " vs " << b[i];
}

// Time and position bit-exact; rotation through the quaternion text.
inline void ExpectSamePose(double ta, const Eigen::Isometry3d& a, double tb, const Eigen::Isometry3d& b) {
  EXPECT_TRUE(SameBits(ta, tb));
  ExpectSameBits(a.translation(), b.translation());
  EXPECT_LE((a.linear() - b.linear()).cwiseAbs().maxCoeff(), kRotationRoundTrip);
  EXPECT_LE((b.linear().transpose() * b.linear() - Eigen::Matrix3d::Identity()).norm(), kRotationRoundTrip);
}

inline void ExpectSameImu(const ImuSample& a, const ImuSample& b) {
  EXPECT_TRUE(SameBits(a.time_s, b.time_s));
  ExpectSameBits(a.accel_m_s2, b.accel_m_s2);
  ExpectSameBits(a.gyro_rad_s, b.gyro_rad_s);
}

inline void ExpectSameScan(const ScanRecord& a, const ScanRecord& b) {
  ASSERT_EQ(a.index(), b.index());
  if (const auto* la = std::get_if<LineScan>(&a)) {
    const LineScan& lb = std::get<LineScan>(b);
    for (auto f : {&LineScan::start_time_s, &LineScan::angle_min_rad, &LineScan::angle_increment_rad,
                   &LineScan::time_increment_s, &LineScan::range_min_m, &LineScan::range_max_m}) {
      EXPECT_TRUE(SameBits(la->*f, lb.*f));
    }
    ASSERT_EQ(la->ranges_m.size(), lb.ranges_m.size());
    ASSERT_EQ(la->intensities.size(), lb.intensities.size());
    // (memcmp of an empty vector's null data() is undefined: UBSan reports it)
    if (!la->ranges_m.empty()) {
      EXPECT_EQ(std::memcmp(la->ranges_m.data(), lb.ranges_m.data(), 4 * la->ranges_m.size()), 0);
    }
    if (!la->intensities.empty()) {
      EXPECT_EQ(std::memcmp(la->intensities.data(), lb.intensities.data(), 4 * la->intensities.size()), 0);
    }
    return;
  }
  const RawScan& ra = std::get<RawScan>(a);
  const RawScan& rb = std::get<RawScan>(b);
  EXPECT_TRUE(SameBits(ra.start_time_s, rb.start_time_s));
  EXPECT_TRUE(SameBits(ra.end_time_s, rb.end_time_s));
  EXPECT_EQ(ra.has_point_time, rb.has_point_time);
  ASSERT_EQ(ra.points.size(), rb.points.size());
  for (std::size_t i = 0; i < ra.points.size(); ++i) {
    ExpectSameBits(ra.points[i].position_m, rb.points[i].position_m);
    EXPECT_TRUE(SameBits(ra.points[i].time_s, rb.points[i].time_s));
    EXPECT_TRUE(SameBits(ra.points[i].intensity, rb.points[i].intensity));
    EXPECT_EQ(ra.points[i].ring, rb.points[i].ring);
  }
}

}  // namespace unimap::io::test
