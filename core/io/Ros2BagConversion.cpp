// ConvertRos2Bag (io/DatasetConversion.hpp): a ROS 2 bag into a dataset.
#include "io/BagConversion.hpp"
#include "io/DatasetConversion.hpp"
#include "io/Ros2BagReader.hpp"

namespace unimap::io {

ConversionReport ConvertRos2Bag(const ConversionOptions& options) {
  Ros2BagReader reader(options.input, options.rosbag);
  const RosbagTopics& selected = reader.selected();
  ConversionReport report = WriteBagDataset(options, "ros2bag", reader);
  std::string angle = "angle (encoder) topic: (none)";
  if (!selected.angle.empty()) {
    const std::string type = reader.DatatypeOf(selected.angle);
    const bool degrees = options.rosbag.angle_unit == AngleUnit::kDegrees;
    angle = "angle (encoder) topic: " + selected.angle + " (" + type + ", " + (degrees ? "deg" : "rad") +
            "): its times are the bag's receive times (the message has no header stamp)";
  }
  report.notes.push_back(angle);
  return report;
}

}  // namespace unimap::io
