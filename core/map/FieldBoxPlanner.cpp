#include "map/FieldBoxPlanner.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::map {

FieldBoxPlanner::FieldBoxPlanner(const DistanceMapOptions& options, double resolution_m)
    : range_cells_(std::max(1, static_cast<int>(std::lround(options.max_range_m / resolution_m)))),
      clamp_cells_(static_cast<int>(std::ceil(options.clamp_distance_m / resolution_m - 1e-9))),
      margin_cells_(static_cast<int>(std::ceil(options.growth_margin_m / resolution_m - 1e-9))),
      recenter_cells_(options.recenter_fraction * options.max_range_m / resolution_m),
      max_cells_(options.max_edt_cells) {}

KeyBox FieldBoxPlanner::SensorBox(const Eigen::Vector3i& center_key) const {
  const Eigen::Vector3i half = Eigen::Vector3i::Constant(range_cells_);
  return KeyBox(center_key - half, center_key + half);
}

KeyBox FieldBoxPlanner::FieldBox(const KeyBox& occupied, const KeyBox& sensor_box, const Eigen::Vector3i& center_key,
                                 bool* shrunk) const {
  const KeyBox inflated = occupied.Inflated(clamp_cells_);
  KeyBox field = inflated.Intersection(sensor_box);
  int half = range_cells_;
  while (field.CellCount() > max_cells_ && half > 1) {
    half = std::max(1, (half * 9) / 10);
    const Eigen::Vector3i h = Eigen::Vector3i::Constant(half);
    field = inflated.Intersection(sensor_box).Intersection(KeyBox(center_key - h, center_key + h));
    if (shrunk != nullptr) *shrunk = true;
  }
  return field;
}

KeyBox FieldBoxPlanner::GrownOccupied(const KeyBox& occupied, const KeyBox& endpoints, const KeyBox& sensor_box) const {
  const KeyBox fresh = endpoints.Intersection(sensor_box);
  if (occupied.Contains(fresh)) return occupied;
  KeyBox grown = occupied;
  grown.Extend(fresh);
  return grown.Inflated(margin_cells_).Intersection(sensor_box);
}

bool FieldBoxPlanner::NeedsRecenter(const Eigen::Vector3i& center_key, const Eigen::Vector3i& sensor_key) const {
  const int offset = (sensor_key - center_key).cwiseAbs().maxCoeff();
  return static_cast<double>(offset) > recenter_cells_;
}

}  // namespace unimap::map
