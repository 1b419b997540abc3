#pragma once
// Reading a unimap dataset folder (docs/dataset_format.md) through the
// public API: its events in time order, as `unimap run` feeds them.
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "unimap/EncoderSample.hpp"
#include "unimap/Export.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/LineScan.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/RawScan.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap {

// One time-stamped item of a dataset.
using DatasetEvent = std::variant<ImuSample, EncoderSample, OdometrySample, RawScan, LineScan>;

// What a dataset's metadata.yaml says about it.
struct DatasetInfo {
  std::string payload;           // payload plugin the scans are for ("rotating_2d")
  std::string scenario;          // simulated scenario, empty for real data
  double duration_s = 0.0;       // time span of the data (s)
  bool has_imu = false;          // imu.csv holds samples
  bool has_encoder = false;      // encoder.csv holds samples
  bool has_odometry = false;     // odometry.csv holds samples
  bool has_groundtruth = false;  // groundtruth.tum exists
};

// Streams a dataset folder (one item per stream held, not the whole data).
// Throws unimap::ConfigError or InputError naming the file and line or
// record (a missing folder or metadata.yaml, a malformed record, time going
// backwards within a file).
class UNIMAP_MAPPER_API Dataset {
 public:
  explicit Dataset(const std::string& folder);
  ~Dataset();
  Dataset(const Dataset&) = delete;
  Dataset& operator=(const Dataset&) = delete;

  const DatasetInfo& info() const;
  // The next event of all streams merged in time order (scans by their end
  // time; ties: IMU, encoder, odometry, scans); nullopt at the end.
  std::optional<DatasetEvent> Next();
  // The ground truth (groundtruth.tum; empty when there is none).
  std::vector<StampedPose> GroundTruth() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap
