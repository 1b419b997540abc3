// OpenDatasetSink and Convert (io/DatasetConversion.hpp).
#include "io/DatasetConversion.hpp"

#include "io/DatasetWriter.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {

std::unique_ptr<DatasetSink> OpenDatasetSink(const ConversionOptions& options, const DatasetMetadata& metadata) {
  if (options.open_sink) return options.open_sink(metadata);
  return std::make_unique<DatasetWriter>(options.output, metadata);
}

ConversionReport Convert(const std::string& format, const ConversionOptions& options) {
  if (format == "kitti") return ConvertKitti(options);
  if (format == "carmen") return ConvertCarmen(options);
  if (format == "rosbag") return ConvertRosbag(options);
  if (format == "ros2") return ConvertRos2Bag(options);
  throw InputError(options.input.string() + ": unknown recording format '" + format +
                   "' (kitti, carmen, rosbag or ros2)");
}

}  // namespace unimap::io
