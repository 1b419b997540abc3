#pragma once
// Real data (KITTI, CARMEN, ROS 1 and ROS 2 bags) into the dataset format
// (docs/dataset-format.md), streamed: `unimap convert` and tests call these.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/BagClockAligner.hpp"
#include "io/CarmenReader.hpp"
#include "io/DatasetMetadata.hpp"
#include "io/DatasetSink.hpp"
#include "io/KittiReader.hpp"
#include "io/RosbagReader.hpp"

namespace unimap::io {

// Where CARMEN odometry comes from.
enum class CarmenOdometrySource {
  kAuto,         // ODOM lines when the log has any, else the FLASER odom fields
  kOdomLines,    // ODOM lines only
  kLaserFields,  // odom_x odom_y odom_theta of each FLASER line
};

struct ConversionOptions {
  std::filesystem::path input;    // KITTI folder, CARMEN log, ROS 1 bag file, ROS 2 bag folder or .db3
  std::filesystem::path output;   // dataset folder to write
  std::string payload;            // metadata payload name; empty = the format's default
  double reorder_window_s = 2.0;  // how late an item may arrive and still be put in time order
  KittiReaderOptions kitti;       // side files of a KITTI sequence
  CarmenReaderOptions carmen;     // FLASER beam layout
  CarmenOdometrySource carmen_odometry = CarmenOdometrySource::kAuto;
  RosbagReaderOptions rosbag;               // topic choice (ROS 1 and ROS 2 bags), scalar angle unit
  BagClockOptions clocks;                   // bags: topics stamped on different clocks (BagClockAligner)
  const std::atomic<bool>* stop = nullptr;  // when set (e.g. by a signal): stop reading, finish the dataset
  // Where the items go, given the dataset's metadata (called once, before
  // the first item); empty: a DatasetWriter of `output`.
  std::function<std::unique_ptr<DatasetSink>(const DatasetMetadata&)> open_sink;
};

// What a conversion wrote and left out.
struct ConversionReport {
  std::string payload;                         // payload written to metadata.yaml
  std::size_t scans = 0;                       // records in scans.bin
  std::size_t imu = 0;                         // IMU samples
  std::size_t encoder = 0;                     // encoder samples
  std::size_t odometry = 0;                    // odometry samples
  std::size_t groundtruth = 0;                 // ground-truth poses
  std::size_t dropped_points = 0;              // scan points left out (non-finite)
  std::map<std::string, std::size_t> skipped;  // reason -> items (lines, messages) not converted
  std::vector<std::string> notes;              // choices made (topics, calibration, odometry source)
  bool interrupted = false;                    // stopped early by ConversionOptions::stop: the dataset
                                               // holds what was read before
};

// options.open_sink(metadata), or a DatasetWriter of options.output.
std::unique_ptr<DatasetSink> OpenDatasetSink(const ConversionOptions& options, const DatasetMetadata& metadata);

// Each reads `options.input` and writes `options.output` (or the sink
// options.open_sink makes); throws InputError (bad input, naming file and
// line / topic) or ConfigError.
ConversionReport ConvertKitti(const ConversionOptions& options);
ConversionReport ConvertCarmen(const ConversionOptions& options);
ConversionReport ConvertRosbag(const ConversionOptions& options);   // throws InputError for a ROS 2 bag
ConversionReport ConvertRos2Bag(const ConversionOptions& options);  // see Ros2BagReader
// The one of the four `format` names ("kitti", "carmen", "rosbag", "ros2":
// `unimap convert --format`); InputError for another name.
ConversionReport Convert(const std::string& format, const ConversionOptions& options);

}  // namespace unimap::io
