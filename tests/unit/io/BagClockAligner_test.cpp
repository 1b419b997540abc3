#include "io/BagClockAligner.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// A line scan on topic, stamped stamp_s, received at receive_s.
RosbagMessage Line(const std::string& topic, double stamp_s, double receive_s) {
  RosbagMessage m;
  m.topic = topic;
  m.stamp_s = stamp_s;
  m.receive_s = receive_s;
  LineScan scan;
  scan.start_time_s = stamp_s;
  m.data = scan;
  return m;
}

// An encoder sample stamped on receipt (no header).
RosbagMessage Angle(const std::string& topic, double receive_s) {
  RosbagMessage m;
  m.topic = topic;
  m.stamp_s = receive_s;
  m.receive_s = receive_s;
  m.data = EncoderSample{receive_s, 0.5};
  return m;
}

// Scans on a device clock 1000 s behind the receive clock (with 5-15 ms of
// transport delay), angles stamped on receipt, interleaved for 5 s.
std::vector<RosbagMessage> DisagreeingBag() {
  std::vector<RosbagMessage> bag;
  for (int k = 0; k < 50; ++k) {
    const double t = 100.0 + 0.1 * k;
    bag.push_back(Line("/scan", t - 1000.0, t + 0.005 + 0.01 * (k % 2)));
    bag.push_back(Angle("/angle", t + 0.05));
  }
  return bag;
}

std::vector<RosbagMessage> Align(const std::vector<RosbagMessage>& bag, BagClockOptions options,
                                 std::vector<std::string>* notes) {
  BagClockAligner aligner(options, notes);
  std::vector<RosbagMessage> out;
  for (const RosbagMessage& m : bag) aligner.Push(m, &out);
  aligner.Finish(&out);
  return out;
}

TEST(BagClockAlignerTest, TopicsOnDifferentClocksMoveOntoTheReceiveClock) {
  std::vector<std::string> notes;
  const std::vector<RosbagMessage> out = Align(DisagreeingBag(), {}, &notes);
  ASSERT_EQ(out.size(), 100u);
  // Order kept; each scan moved by the median delay-inclusive offset
  // (1000.015 s: half the first 20 have 15 ms), keeping its spacing.
  EXPECT_EQ(out[0].topic, "/scan");
  const double moved = std::get<LineScan>(out[0].data).start_time_s;
  EXPECT_NEAR(moved, 100.015, 1e-9);
  EXPECT_NEAR(out[0].stamp_s, 100.015, 1e-9);
  EXPECT_NEAR(std::get<LineScan>(out[2].data).start_time_s - moved, 0.1, 1e-9);
  // The angles were already on the receive clock.
  EXPECT_NEAR(std::get<EncoderSample>(out[1].data).time_s, 100.05, 1e-12);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("/scan is stamped 1000.015 s behind"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("/scan moved by +1000.015 s"), std::string::npos) << notes[1];
}

TEST(BagClockAlignerTest, AgreeingClocksAreKept) {
  std::vector<RosbagMessage> bag;
  for (int k = 0; k < 30; ++k) {
    bag.push_back(Line("/scan", 10.0 + 0.1 * k, 10.02 + 0.1 * k));
    bag.push_back(Angle("/angle", 10.05 + 0.1 * k));
  }
  std::vector<std::string> notes;
  const std::vector<RosbagMessage> out = Align(bag, {}, &notes);
  ASSERT_EQ(out.size(), bag.size());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i].stamp_s, bag[i].stamp_s);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("times kept as stamped"), std::string::npos) << notes[0];
}

TEST(BagClockAlignerTest, WithoutAlignmentDisagreementIsAnError) {
  BagClockOptions options;
  options.align = false;
  std::vector<std::string> notes;
  try {
    Align(DisagreeingBag(), options, &notes);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("different clocks"), std::string::npos) << what;
    EXPECT_NE(what.find("/scan"), std::string::npos) << what;
    EXPECT_NE(what.find("/angle"), std::string::npos) << what;
  }
}

TEST(BagClockAlignerTest, DecidesWithinTheWindowAndMovesLateTopicsByTheirOwnOffset) {
  // Only scans for 12 s (more than the 10 s window): decided without the
  // angles; an angle topic appearing later on another clock is moved by its
  // own first offset.
  std::vector<RosbagMessage> bag;
  for (int k = 0; k < 120; ++k) bag.push_back(Line("/scan", 0.1 * k, 500.0 + 0.1 * k));
  std::vector<std::string> notes;
  BagClockAligner aligner({}, &notes);
  std::vector<RosbagMessage> out;
  for (const RosbagMessage& m : bag) aligner.Push(m, &out);
  EXPECT_EQ(out.size(), 120u);  // released once decided (all: one topic, 20 samples)
  RosbagMessage late = Line("/late", 7.0, 512.5);
  aligner.Push(late, &out);
  aligner.Finish(&out);
  ASSERT_EQ(out.size(), 121u);
  EXPECT_EQ(out.back().stamp_s, 7.0);  // one topic: nothing disagreed, nothing moved
}

TEST(BagClockAlignerTest, ShiftMovesEveryTimeAMessageCarries) {
  RosbagMessage cloud;
  RawScan scan;
  scan.start_time_s = 1.0;
  scan.end_time_s = 1.1;
  Point p;
  p.time_s = 1.05;
  scan.points.push_back(p);
  cloud.stamp_s = 1.1;
  cloud.data = scan;
  ShiftMessageTimes(&cloud, 10.0);
  const RawScan& moved = std::get<RawScan>(cloud.data);
  EXPECT_DOUBLE_EQ(moved.start_time_s, 11.0);
  EXPECT_DOUBLE_EQ(moved.end_time_s, 11.1);
  EXPECT_DOUBLE_EQ(moved.points[0].time_s, 11.05);
  EXPECT_DOUBLE_EQ(cloud.stamp_s, 11.1);
  RosbagMessage imu;
  imu.data = ImuSample{2.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  ShiftMessageTimes(&imu, -1.5);
  EXPECT_DOUBLE_EQ(std::get<ImuSample>(imu.data).time_s, 0.5);
}

}  // namespace
}  // namespace unimap::io
