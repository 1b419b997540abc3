// ConvertRosbag (io/DatasetConversion.hpp): a ROS 1 bag into a dataset.
#include "io/BagConversion.hpp"
#include "io/DatasetConversion.hpp"

namespace unimap::io {

ConversionReport ConvertRosbag(const ConversionOptions& options) {
  RosbagReader reader(options.input, options.rosbag);
  return WriteBagDataset(options, "rosbag", reader);
}

}  // namespace unimap::io
