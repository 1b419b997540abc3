#pragma once
// Fixed inputs for the stage micro-benchmarks: a few seconds of a simulated
// scenario with one payload, deskewed with the true motion, so that every
// stage runs on realistic data without depending on the stages before it.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "io/ScanRecord.hpp"
#include "pipeline/LocalizerOptions.hpp"
#include "pipeline/PoseHistory.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/Platform.hpp"
#include "unimap/RawScan.hpp"

namespace unimap::bench {

// One 3D scan as the localiser inserts it: N scans in the map frame (true
// poses), one point per map voxel, and the mean sensor position.
struct KeyScanInput {
  std::vector<Eigen::Vector3f> points_map;
  Eigen::Vector3f sensor_map = Eigen::Vector3f::Zero();
};

struct StageInputs {
  std::string name;                                      // "corridor_loop / fixed_vlp16"
  Platform platform;                                     // holds the plugin
  pipeline::LocalizerOptions options;                    // FromPlatform
  std::vector<RawScan> raw_scans;                        // as the plugin receives them (line scans converted)
  EncoderTrack encoder;                                  // the whole recorded encoder stream
  pipeline::PoseHistory truth{1e9};                      // true body poses
  std::vector<std::vector<Eigen::Vector3f>> body_scans;  // deskewed with the true motion
  std::vector<Eigen::Isometry3d> body_poses;             // true T_map_body at each scan's reference time
  std::vector<KeyScanInput> key_scans;                   // every N scans
  double duration_s = 0.0;                               // data simulated
};

// The inputs of configs/scenarios/<scenario>.yaml with
// configs/platforms/<platform>.yaml over its first duration_s seconds,
// simulated once per process (cached by name).
const StageInputs& Inputs(const std::string& scenario, const std::string& platform, double duration_s);

}  // namespace unimap::bench
