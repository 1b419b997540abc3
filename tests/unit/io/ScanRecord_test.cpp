#include "io/ScanRecord.hpp"

#include <gtest/gtest.h>

namespace unimap::io {
namespace {

TEST(ScanRecord, LineScanEndsAtItsLastBeam) {
  LineScan line;
  line.start_time_s = 10.0;
  line.time_increment_s = 0.25;
  line.ranges_m.assign(5, 1.0f);
  // t_end = t_0 + (n - 1) dt = 10 + 4 * 0.25.
  EXPECT_EQ(ScanEndTime(ScanRecord(line)), 11.0);
  EXPECT_EQ(ScanStartTime(ScanRecord(line)), 10.0);
  // Same value LineScanToRawScan gives the converted scan.
  EXPECT_EQ(ScanEndTime(ScanRecord(line)), LineScanToRawScan(line).scan.end_time_s);
}

TEST(ScanRecord, LineScanWithoutBeamsEndsWhenItStarts) {
  LineScan line;
  line.start_time_s = 3.5;
  line.time_increment_s = 1.0;
  EXPECT_EQ(ScanEndTime(ScanRecord(line)), 3.5);
}

TEST(ScanRecord, RawScanUsesItsStartAndEndTimes) {
  RawScan raw;
  raw.start_time_s = 1.0;
  raw.end_time_s = 1.1;
  Point p;
  p.time_s = 5.0;  // point times do not matter: the header fields do
  raw.points.push_back(p);
  EXPECT_EQ(ScanEndTime(ScanRecord(raw)), 1.1);
  EXPECT_EQ(ScanStartTime(ScanRecord(raw)), 1.0);
}

}  // namespace
}  // namespace unimap::io
