// ConvertRosbag (io/DatasetConversion.hpp): a ROS 1 bag into a dataset.
#include "io/BagConversion.hpp"
#include "io/DatasetConversion.hpp"

namespace unimap::io {

ConversionReport ConvertRosbag(const ConversionOptions& options) {
  RosbagReader reader(options.input, options.rosbag);
  const RosbagTopics& selected = reader.selected();
  ConversionReport report = WriteBagDataset(options, "rosbag", reader);
  if (!selected.angle.empty()) {
    const std::string type = reader.DatatypeOf(selected.angle);
    const std::string field = options.rosbag.angle_field.empty() ? "data" : options.rosbag.angle_field;
    const bool degrees = options.rosbag.angle_unit == AngleUnit::kDegrees;
    report.notes.push_back("angle (encoder) topic: " + selected.angle + " (" + type + ", field " + field + ", " +
                           (degrees ? "deg" : "rad") + ", read by the bag's message definition): " +
                           (selected.angle == selected.laser ? "stamped with its line's header stamp"
                                                             : "stamped by its header, else the receive time"));
  }
  return report;
}

}  // namespace unimap::io
