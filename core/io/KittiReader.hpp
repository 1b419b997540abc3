#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/RawScan.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Where the side files of a KITTI odometry sequence are; empty = found next
// to the scans (see KittiReader).
struct KittiReaderOptions {
  std::filesystem::path poses_file;  // 3x4 row-major camera poses, one line per frame; empty: auto
  std::filesystem::path times_file;  // one time (s) per frame; empty: auto, else index * scan_period_s
  std::filesystem::path calib_file;  // calib.txt with a "Tr:" line; empty: auto, else sequence 00's Tr
  double scan_period_s = 0.1;        // HDL-64E sweep period (10 Hz)
};

// One scan of the sequence.
struct KittiFrame {
  std::size_t index = 0;           // frame number (from the file name, e.g. 000015.pcd -> 15)
  std::filesystem::path file;      // the scan file
  RawScan scan;                    // LiDAR frame; has_point_time false (see KittiReader::Read)
  std::size_t dropped_points = 0;  // non-finite points left out
};

// Reads a KITTI odometry sequence: scans as `.bin` (float32 x y z
// reflectance per point) or `.pcd` (through PCL), in the folder given or its
// `velodyne/` subfolder, ordered by file name. Side files are looked up in
// the folder, then its parent: times.txt; calib.txt; poses as
// poses_camera_frame.txt or poses.txt. Poses are converted to the LiDAR frame
// (T_lidar0_lidari = Tr^-1 * T_cam0_cami * Tr, Tr = T_cam_lidar from calib.txt).
class KittiReader {
 public:
  // Lists the scans and reads the side files; throws InputError for a folder
  // without scans, mixed .bin/.pcd, malformed side files (naming file and
  // line) or fewer times/poses than the highest frame number needs.
  explicit KittiReader(const std::filesystem::path& folder, KittiReaderOptions options = {});

  std::size_t size() const { return files_.size(); }
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // Frame number of the i-th scan file.
  std::size_t frame_index(std::size_t i) const { return indices_[i]; }
  // Reads the i-th scan file (i < size()). start_time_s is the frame's time,
  // end_time_s = start + scan_period_s; every point's time_s is the start
  // time and has_point_time is false: the fixed_3d plugin derives firing
  // times from azimuth. Throws InputError for a damaged file.
  KittiFrame Read(std::size_t i) const;
  // The next scan in file order; std::nullopt after the last one.
  std::optional<KittiFrame> Next();

  bool has_poses() const { return !lidar_poses_.empty(); }
  // LiDAR pose of each scan file (same order as files()), T_map_body with
  // map = LiDAR frame of frame 0, body = LiDAR; empty without a poses file.
  const std::vector<StampedPose>& lidar_poses() const { return lidar_poses_; }
  // Tr = T_cam_lidar in use, and where it came from (a file or "sequence 00 default").
  const Eigen::Isometry3d& T_cam_lidar() const { return T_cam_lidar_; }
  const std::string& calibration_source() const { return calibration_source_; }

  // Sequence 00's Tr (velodyne to left camera), from KITTI's calib.txt.
  static Eigen::Isometry3d DefaultTcamLidar();
  // Reads a 3x4 row-major pose per line ('#' and blank lines skipped);
  // rotations are re-orthonormalised. Throws InputError "<file>:<line>: ...".
  static std::vector<Eigen::Isometry3d> ReadPoses(const std::filesystem::path& file);
  // Reads the "Tr:" (or "Tr_velo_to_cam:") line of a calib.txt.
  static Eigen::Isometry3d ReadCalibration(const std::filesystem::path& file);
  // Reads one number per line. Throws InputError "<file>:<line>: ...".
  static std::vector<double> ReadTimes(const std::filesystem::path& file);

 private:
  KittiReaderOptions options_;
  std::vector<std::filesystem::path> files_;  // scan files, sorted
  std::vector<std::size_t> indices_;          // frame number per file
  std::vector<double> times_s_;               // time per file
  std::vector<StampedPose> lidar_poses_;      // LiDAR pose per file (or empty)
  Eigen::Isometry3d T_cam_lidar_ = Eigen::Isometry3d::Identity();
  std::string calibration_source_;
  std::size_t next_ = 0;  // next file for Next()
};

}  // namespace unimap::io
