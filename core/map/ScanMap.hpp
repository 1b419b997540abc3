#pragma once
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceField.hpp"

namespace unimap::map {

// Time a map spent keeping itself up to date (wall seconds, summed).
struct MapUpdateTimes {
  double surface_s = 0.0;   // integrating returns into the surface (occupancy, elements)
  double distance_s = 0.0;  // updating the distances
  double export_s = 0.0;    // publishing fields
  MapUpdateTimes& operator+=(const MapUpdateTimes& other) {
    surface_s += other.surface_s;
    distance_s += other.distance_s;
    export_s += other.export_s;
    return *this;
  }
};

// What the localiser needs from a map: distance-field snapshots to match
// against and a place to insert 3D scans. Implemented by DistanceMap (one
// map, e.g. a prior) and SubmapManager (the paper's matching and growing
// submaps). Implementations are thread-safe.
class ScanMap {
 public:
  virtual ~ScanMap() = default;
  // The field to match against now (never null; empty until the first update).
  virtual std::shared_ptr<const DistanceField> Snapshot() const = 0;
  // Queues a 3D scan (points and sensor origin in the map frame). Throws
  // InputError for a non-finite origin or one outside the map's key range.
  virtual void InsertScan(std::vector<Eigen::Vector3f> points_map, const Eigen::Vector3f& sensor_origin_map) = 0;
  // Where the sensor is (lets distance boxes follow it). Same errors as InsertScan.
  virtual void UpdateSensorPosition(const Eigen::Vector3f& sensor_map) = 0;
  // Blocks until everything queued so far is published; rethrows a
  // background update's error once.
  virtual void WaitForUpdates() = 0;
  // Time spent on updates so far (zeros when the map does not measure it).
  virtual MapUpdateTimes UpdateTimes() const { return {}; }
};

}  // namespace unimap::map
