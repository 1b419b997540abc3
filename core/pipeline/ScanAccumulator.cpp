#include "pipeline/ScanAccumulator.hpp"

namespace unimap::pipeline {

bool ScanAccumulator::Add(const std::vector<Eigen::Vector3f>& points_map, const std::vector<float>& intensities,
                          const Eigen::Vector3f& sensor_map, const std::vector<Eigen::Vector3f>& map_only_points) {
  points_.insert(points_.end(), points_map.begin(), points_map.end());
  all_intensities_ = all_intensities_ && intensities.size() == points_map.size();
  if (all_intensities_) intensities_.insert(intensities_.end(), intensities.begin(), intensities.end());
  map_only_points_.insert(map_only_points_.end(), map_only_points.begin(), map_only_points.end());
  sensor_sum_ += sensor_map;
  ++count_;
  return count_ >= n_;
}

std::vector<Eigen::Vector3f> ScanAccumulator::Take(Eigen::Vector3f* sensor_map, std::vector<float>* intensities,
                                                   std::vector<Eigen::Vector3f>* map_only_points) {
  *sensor_map = count_ > 0 ? Eigen::Vector3f(sensor_sum_ / static_cast<float>(count_)) : sensor_sum_;
  std::vector<Eigen::Vector3f> out;
  out.swap(points_);
  intensities->clear();
  if (all_intensities_) intensities->swap(intensities_);
  intensities_.clear();
  all_intensities_ = true;
  if (map_only_points != nullptr) map_only_points->swap(map_only_points_);
  map_only_points_.clear();
  count_ = 0;
  sensor_sum_.setZero();
  return out;
}

}  // namespace unimap::pipeline
