#pragma once
// The online mapper: unimap as a library (docs/library.md). Feed sensor
// data as it arrives; read poses, the trajectory and the map.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "unimap/EncoderSample.hpp"
#include "unimap/Export.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/LineScan.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/RawScan.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap {

// Version of this API: bumped on any incompatible change (as kPluginAbiVersion).
inline constexpr int kMapperApiVersion = 1;

// How calls are processed.
enum class MapperMode {
  kSynchronous,  // on the caller's thread; waits for every map update: the
                 // same results as `unimap run` on the same data
  kLive,         // on a worker thread; Add* never waits for processing, the
                 // map and the pose graph catch up in the background
};

// The prediction between scans.
enum class MotionModel {
  kImu,               // the IMU (AddImu; the paper's ESKF)
  kOdometry,          // wheel odometry (AddOdometry)
  kConstantVelocity,  // neither: the last scans' motion
};

struct MapperSettings {
  std::string platform_file;                   // platform YAML: plugin, parameters, extrinsics
  MapperMode mode = MapperMode::kSynchronous;  // see MapperMode
  MotionModel motion = MotionModel::kImu;      // the prediction; its stream is expected
  bool encoder_stream = true;                  // expect AddEncoder calls when the payload uses an
                                               // encoder (ignored when it does not)
  bool odometry_stream = false;                // expect AddOdometry calls (kOdometry: always)
  int threads = 1;                             // particle-filter threads (1-64; `unimap run --threads`)
  bool loop_closure = true;                    // search for loop closures

  // False (and *why set) when a value is out of range.
  bool IsValid(std::string* why) const;
};

// The filter's pose of one scan, as it was estimated (local odometry frame:
// not moved by later loop closures; Trajectory() has those).
struct MapperPose {
  double time_s = 0.0;                                            // the scan's end time (s)
  Eigen::Isometry3d T_odom_body = Eigen::Isometry3d::Identity();  // body in the odometry frame
  bool matched = false;                                           // the scan was matched to the map
  int points = 0;                                                 // deskewed points of the scan
};

// What the mapper has done so far.
struct MapperStatus {
  std::size_t scans_added = 0;      // AddScan calls accepted
  std::size_t scans_processed = 0;  // scans the localiser has taken
  std::size_t scans_matched = 0;    // of those, matched to the map
  std::size_t key_scans = 0;        // 3D scans in the pose graph
  int submaps = 0;                  // submaps started
  std::size_t loop_closures = 0;    // loop closures accepted
  double lag_s = 0.0;               // newest time added minus newest scan time processed (s)
  std::size_t events_waiting = 0;   // added but not yet processed (waiting for other streams, the worker, or
                                    // the first 3D scan's scans, which size the map: docs/library.md)
};

// One mapper: the paper's system (ESKF + Gaussian particle filter on a
// distance map, submaps, pose graph with loop closures) for one payload.
//
// Streams: each Add* call belongs to a stream (IMU, encoder, odometry,
// scans). Within a stream, times must not decrease (scans by end time);
// across streams calls may come in any order and from one thread per
// stream: events are merged by time before processing (ties: IMU, encoder,
// odometry, scans, as a dataset is read), each waiting until every expected
// stream (MapperSettings) has delivered past it. Times are seconds on one
// clock shared by all streams.
//
// Errors: the constructor throws unimap::ConfigError (bad settings or
// platform file, naming file, line and key) or PluginError; Add* throw
// unimap::InputError for a non-finite time or a time going backwards within
// its stream (the call is ignored); kLive reports a processing error on the
// next call. The mapper is built once the first 3D scan's scans have arrived
// (they size the map's voxel, docs/library.md): a `mapper:` value that is
// invalid only at the voxel the scene chose throws ConfigError from the Add*
// call (kLive: the next call) or Finish() that builds it. Everything else is
// reported by the return values.
class UNIMAP_MAPPER_API Mapper {
 public:
  // Loads the platform file and its payload plugin (searched as `unimap run`
  // does: UNIMAP_PLUGIN_PATH, then the install's plugin folder).
  explicit Mapper(const MapperSettings& settings);
  // The same with default settings.
  explicit Mapper(const std::string& platform_file);
  // Stops the worker; data not yet processed is dropped (call Finish first).
  ~Mapper();
  Mapper(const Mapper&) = delete;
  Mapper& operator=(const Mapper&) = delete;

  // An IMU sample: body-frame angular rate (rad/s) and specific force (m/s^2).
  void AddImu(const ImuSample& sample);
  // A motor encoder reading (rad), for payloads on a motor.
  void AddEncoder(const EncoderSample& sample);
  // A wheel-odometry pose (MotionModel::kOdometry).
  void AddOdometry(const OdometrySample& sample);
  // A 3D sweep or 2D line in the LiDAR frame, as the sensor delivered it.
  void AddScan(const RawScan& scan);
  void AddScan(const LineScan& scan);

  // Called with each scan's pose as it is estimated, on the thread that
  // processed it (the caller's in kSynchronous, the worker's in kLive);
  // set before the first Add*. It must not call back into the Mapper.
  void SetPoseCallback(std::function<void(const MapperPose&)> callback);

  // End of data: processes everything still waiting (whatever streams have
  // not delivered), then optimises the pose graph a last time. Blocks until
  // done. Add* calls after it throw InputError.
  void Finish();

  // Every scan pose so far, in time order (see MapperPose).
  std::vector<MapperPose> Poses() const;
  // Every scan pose so far in the world frame, corrected by the optimised
  // pose graph (after Finish: the final trajectory, as trajectory.tum).
  std::vector<StampedPose> Trajectory() const;
  // The map: key scans' points in the world frame (optimised poses), one
  // per voxel of edge voxel_m (as map.ply with the default 0.1 m).
  std::vector<Eigen::Vector3f> MapPoints(double voxel_m = 0.1) const;
  // Writes MapPoints(voxel_m) to path: binary PLY (.ply) or PCD (.pcd),
  // written completely or not at all. Throws InputError for another
  // extension or when the file cannot be written.
  void WriteMap(const std::string& path, double voxel_m = 0.1) const;
  MapperStatus Status() const;
  // The payload plugin's name (e.g. "rotating_2d").
  std::string PayloadName() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap
