#pragma once
#include <Eigen/Core>

#include "map/DistanceMapOptions.hpp"
#include "map/KeyBox.hpp"

namespace unimap::map {

// Where the distance map keeps distances: the sensor box (max_range_m per
// axis around the box centre) clipped to the occupied voxels in it inflated
// by the clamp distance, so a 6 m wide tunnel does not allocate a 30 m cube.
// All boxes are in octree key coordinates.
class FieldBoxPlanner {
 public:
  // resolution_m is the octree's (it may differ from options for loaded maps).
  FieldBoxPlanner(const DistanceMapOptions& options, double resolution_m);

  // Voxels within max_range_m (per axis) of the centre voxel.
  KeyBox SensorBox(const Eigen::Vector3i& center_key) const;
  // (occupied inflated by the clamp) intersected with sensor_box: every voxel
  // of sensor_box closer than the clamp to an occupied voxel of sensor_box.
  // Above max_edt_cells the sensor box is shrunk about center_key until the
  // result fits, and *shrunk is set (left untouched otherwise).
  KeyBox FieldBox(const KeyBox& occupied, const KeyBox& sensor_box, const Eigen::Vector3i& center_key,
                  bool* shrunk) const;
  // occupied grown by the endpoints of new returns inside sensor_box, plus
  // the growth margin on every side; equals occupied when nothing is new.
  KeyBox GrownOccupied(const KeyBox& occupied, const KeyBox& endpoints, const KeyBox& sensor_box) const;
  // True when the sensor is farther than recenter_fraction * max_range_m
  // from the box centre along any axis.
  bool NeedsRecenter(const Eigen::Vector3i& center_key, const Eigen::Vector3i& sensor_key) const;

  int range_cells() const { return range_cells_; }  // max_range_m in voxels
  int clamp_cells() const { return clamp_cells_; }  // clamp distance in voxels (rounded up)

 private:
  int range_cells_;
  int clamp_cells_;
  int margin_cells_;
  double recenter_cells_;
  std::size_t max_cells_;
};

}  // namespace unimap::map
