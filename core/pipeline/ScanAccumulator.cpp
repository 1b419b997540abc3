#include "pipeline/ScanAccumulator.hpp"

namespace unimap::pipeline {

bool ScanAccumulator::Add(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& sensor_map) {
  points_.insert(points_.end(), points_map.begin(), points_map.end());
  sensor_sum_ += sensor_map;
  ++count_;
  return count_ >= n_;
}

std::vector<Eigen::Vector3f> ScanAccumulator::Take(Eigen::Vector3f* sensor_map) {
  *sensor_map = count_ > 0 ? Eigen::Vector3f(sensor_sum_ / static_cast<float>(count_)) : sensor_sum_;
  std::vector<Eigen::Vector3f> out;
  out.swap(points_);
  count_ = 0;
  sensor_sum_.setZero();
  return out;
}

}  // namespace unimap::pipeline
