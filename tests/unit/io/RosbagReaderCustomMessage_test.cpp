// RosbagReader on custom ROS 1 messages, read by the definition the bag
// carries: the tilting stand's pcg_node/LaserScanAngle (a LaserScan and a
// float64 stepAngle in degrees) from ../shared/data/tilting_hokuyo.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "io/RosbagReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

const fs::path kRoomBag = fs::path(UNIMAP_SHARED_DATA_DIR) / "tilting_hokuyo" / "room_240.bag";

#define SKIP_WITHOUT_ROOM_BAG()                                                                                      \
  if (!RosbagReader::Supported()) GTEST_SKIP() << "built without UNIMAP_WITH_ROSBAG (librosbag-storage-dev absent)"; \
  if (!fs::exists(kRoomBag)) GTEST_SKIP() << "real data absent: " << kRoomBag << " (../shared/data not present)"

RosbagReaderOptions StepAngleOptions() {
  RosbagReaderOptions options;
  options.topics.laser = "/slice";
  options.topics.angle = "/slice";
  options.angle_field = "stepAngle";
  options.angle_unit = AngleUnit::kDegrees;
  return options;
}

// The data README: 865 slices, 681 beams, tilt 0.08 -> 60 deg.
TEST(RosbagReaderCustomMessageTest, TiltingStandLinesAndAnglesFromOneMessage) {
  SKIP_WITHOUT_ROOM_BAG();
  RosbagReader reader(kRoomBag, StepAngleOptions());
  EXPECT_EQ(reader.selected().laser, "/slice");
  EXPECT_EQ(reader.selected().angle, "/slice");
  std::size_t lines = 0, angles = 0;
  double lowest = 1e9, highest = -1e9, previous_line_s = -1.0;
  while (auto message = reader.Next()) {
    if (const auto* line = std::get_if<LineScan>(&message->data)) {
      ++lines;
      EXPECT_EQ(line->ranges_m.size(), 681u);
      previous_line_s = message->stamp_s;
    } else if (const auto* encoder = std::get_if<EncoderSample>(&message->data)) {
      ++angles;
      lowest = std::min(lowest, encoder->angle_rad);
      highest = std::max(highest, encoder->angle_rad);
      // Each angle follows its own line, stamped with the line's stamp.
      EXPECT_DOUBLE_EQ(encoder->time_s, previous_line_s);
    }
  }
  EXPECT_EQ(lines, 865u);
  EXPECT_EQ(angles, 865u);
  EXPECT_NEAR(lowest * 180.0 / M_PI, 0.08, 1e-9);
  EXPECT_NEAR(highest * 180.0 / M_PI, 60.0, 1e-9);
}

TEST(RosbagReaderCustomMessageTest, AngleFieldErrorsNameWhatIsMissing) {
  SKIP_WITHOUT_ROOM_BAG();
  RosbagReaderOptions no_unit = StepAngleOptions();
  no_unit.angle_unit = AngleUnit::kUnset;
  try {
    RosbagReader reader(kRoomBag, no_unit);
    FAIL() << "an angle without a unit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--angle-unit"), std::string::npos) << e.what();
  }
  RosbagReaderOptions wrong_field = StepAngleOptions();
  wrong_field.angle_field = "tiltAngle";
  try {
    RosbagReader reader(kRoomBag, wrong_field);
    FAIL() << "a field the message does not have was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/slice"), std::string::npos) << e.what();
  }
  // Without an angle, the custom message still gives its lines.
  RosbagReaderOptions lines_only;
  RosbagReader reader(kRoomBag, lines_only);
  EXPECT_EQ(reader.selected().laser, "/slice");
  EXPECT_EQ(reader.selected().angle, "");
}

}  // namespace
}  // namespace unimap::io
