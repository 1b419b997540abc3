#include "EventMerge.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <variant>
#include <vector>

#include "unimap/Errors.hpp"

namespace unimap::api {
namespace {

constexpr std::array<bool, kStreams> kImuAndScans = {true, false, false, true};

ImuSample Imu(double t) {
  ImuSample s;
  s.time_s = t;
  return s;
}
io::DatasetEvent Sweep(double end_s) {
  RawScan scan;
  scan.start_time_s = end_s - 0.1;
  scan.end_time_s = end_s;
  return io::ScanRecord(scan);
}
// "i<t>" or "s<t>" for each popped event.
std::vector<std::string> Drain(EventMerge* merge, bool flush) {
  std::vector<std::string> out;
  while (std::optional<io::DatasetEvent> e = merge->Pop(flush)) {
    if (const auto* imu = std::get_if<ImuSample>(&*e)) {
      out.push_back("i" + std::to_string(static_cast<int>(imu->time_s)));
    } else if (const auto* enc = std::get_if<EncoderSample>(&*e)) {
      out.push_back("e" + std::to_string(static_cast<int>(enc->time_s)));
    } else {
      out.push_back("s" + std::to_string(static_cast<int>(io::ScanEndTime(std::get<io::ScanRecord>(*e)))));
    }
  }
  return out;
}

TEST(EventMerge, WaitsForEveryExpectedStream) {
  EventMerge merge(kImuAndScans);
  merge.Push(Stream::kScan, 2.0, Sweep(2.0));
  merge.Push(Stream::kScan, 4.0, Sweep(4.0));
  EXPECT_TRUE(Drain(&merge, false).empty());  // the IMU may still deliver something earlier
  merge.Push(Stream::kImu, 1.0, Imu(1.0));
  EXPECT_EQ(Drain(&merge, false), (std::vector<std::string>{"i1"}));  // the IMU queue is empty again
  merge.Push(Stream::kImu, 3.0, Imu(3.0));
  // s4 is queued, so no scan can come before i3; s4 waits for the IMU.
  EXPECT_EQ(Drain(&merge, false), (std::vector<std::string>{"s2", "i3"}));
  EXPECT_EQ(merge.size(), 1u);
  EXPECT_EQ(Drain(&merge, true), (std::vector<std::string>{"s4"}));
  EXPECT_EQ(merge.size(), 0u);
}

TEST(EventMerge, TiesFollowTheDatasetOrder) {
  // IMU, encoder, odometry, scans: as DatasetReader::NextEvent breaks ties.
  EventMerge merge({true, true, false, true});
  merge.Push(Stream::kScan, 5.0, Sweep(5.0));
  EncoderSample enc;
  enc.time_s = 5.0;
  merge.Push(Stream::kEncoder, 5.0, enc);
  merge.Push(Stream::kImu, 5.0, Imu(5.0));
  EXPECT_EQ(Drain(&merge, true), (std::vector<std::string>{"i5", "e5", "s5"}));
}

TEST(EventMerge, OrderDoesNotDependOnHowPushesInterleave) {
  const std::vector<double> imu = {0, 1, 2, 3, 4, 5, 6}, scans = {1, 3, 3, 6};
  const auto run = [&](bool scans_first) {
    EventMerge merge(kImuAndScans);
    std::vector<std::string> out;
    const auto push_scans = [&] {
      for (const double t : scans) merge.Push(Stream::kScan, t, Sweep(t));
    };
    if (scans_first) push_scans();
    for (const double t : imu) {
      merge.Push(Stream::kImu, t, Imu(t));
      for (const std::string& e : Drain(&merge, false)) out.push_back(e);
    }
    if (!scans_first) push_scans();
    for (const std::string& e : Drain(&merge, true)) out.push_back(e);
    return out;
  };
  const std::vector<std::string> expected = {"i0", "i1", "s1", "i2", "i3", "s3", "s3", "i4", "i5", "i6", "s6"};
  EXPECT_EQ(run(true), expected);
  EXPECT_EQ(run(false), expected);
}

TEST(EventMerge, UnexpectedStreamsAreMergedButNotWaitedFor) {
  EventMerge merge(kImuAndScans);
  EncoderSample enc;
  enc.time_s = 0.5;
  merge.Push(Stream::kEncoder, 0.5, enc);
  merge.Push(Stream::kImu, 1.0, Imu(1.0));
  merge.Push(Stream::kScan, 1.0, Sweep(1.0));
  EXPECT_EQ(Drain(&merge, false), (std::vector<std::string>{"e0", "i1"}));
}

TEST(EventMerge, RejectsTimeGoingBackwardsAndNonFiniteTimes) {
  EventMerge merge(kImuAndScans);
  merge.Push(Stream::kImu, 2.0, Imu(2.0));
  try {
    merge.Push(Stream::kImu, 1.5, Imu(1.5));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("IMU time 1.5 s is before the stream's previous 2 s"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(merge.Push(Stream::kScan, std::nan(""), Sweep(0.0)), InputError);
  // Another stream may go back to an earlier time; equal times are accepted.
  merge.Push(Stream::kScan, 1.0, Sweep(1.0));
  merge.Push(Stream::kImu, 2.0, Imu(2.0));
  EXPECT_EQ(merge.size(), 3u);
}

}  // namespace
}  // namespace unimap::api
