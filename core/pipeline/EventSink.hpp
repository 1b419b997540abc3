#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "io/ScanRecord.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/OdometrySample.hpp"

namespace unimap::pipeline {

// The localised pose of one scan.
struct ScanPose {
  double time_s = 0.0;                                      // the scan's reference (end) time
  Eigen::Isometry3d T_map_body = Eigen::Isometry3d::Identity();
  bool matched = false;                                     // a GPF update was applied
  int points = 0;                                           // deskewed body points
};

// What consumes a dataset's events in time order (as DatasetReader::NextEvent
// delivers them) and produces a pose per scan: the Localizer on its own, or
// the Mapper around it.
class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void AddImu(const ImuSample& sample) = 0;
  virtual void AddEncoder(const EncoderSample& sample) = 0;
  virtual void AddScan(io::ScanRecord scan) = 0;
  // A wheel-odometry reading (ignored unless a sink uses it).
  virtual void AddOdometry(const OdometrySample& /*sample*/) {}
  // Processes everything still waiting (end of data).
  virtual void Finish() = 0;
  // Poses produced since the last call, in time order.
  virtual std::vector<ScanPose> TakePoses() = 0;
  // Scans received so far (for progress reports).
  virtual std::size_t ScansReceived() const = 0;
};

}  // namespace unimap::pipeline
