#pragma once
#include <vector>

#include <Eigen/Core>

namespace unimap::pipeline {

// First stage of the paper's two-stage accumulation: N scans (map frame)
// form one 3D scan for map insertion.
class ScanAccumulator {
 public:
  explicit ScanAccumulator(int scans_per_3d_scan) : n_(scans_per_3d_scan) {}

  // Adds one scan's points (map frame) with their intensities (one per
  // point, or none), the sensor position it was taken from and points for
  // the distance map only (e.g. LineGapFill's); returns true when N scans
  // are collected (then call Take).
  bool Add(const std::vector<Eigen::Vector3f>& points_map, const std::vector<float>& intensities,
           const Eigen::Vector3f& sensor_map, const std::vector<Eigen::Vector3f>& map_only_points = {});
  // The 3D scan, the mean sensor position, the points' intensities (one per
  // point when every scan added had them, else empty) and, when asked for,
  // the map-only points; resets the accumulator.
  std::vector<Eigen::Vector3f> Take(Eigen::Vector3f* sensor_map, std::vector<float>* intensities,
                                    std::vector<Eigen::Vector3f>* map_only_points = nullptr);
  int count() const { return count_; }

 private:
  int n_;
  int count_ = 0;
  std::vector<Eigen::Vector3f> points_;
  std::vector<float> intensities_;
  bool all_intensities_ = true;  // every scan added had one intensity per point
  std::vector<Eigen::Vector3f> map_only_points_;
  Eigen::Vector3f sensor_sum_ = Eigen::Vector3f::Zero();
};

}  // namespace unimap::pipeline
