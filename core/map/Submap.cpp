#include "map/Submap.hpp"

#include <cassert>

namespace unimap::map {

Submap::Submap(int id, const Eigen::Vector3d& origin_local, const DistanceMapOptions& options)
    : id_(id),
      T_local_submap_(Eigen::Translation3d(origin_local)),
      map_(std::make_unique<SurfaceDistanceMap>(options)) {}

void Submap::Insert(std::vector<Eigen::Vector3f> points_local, const Eigen::Vector3f& sensor_origin_local) {
  assert(map_ && "Submap::Insert after Retire");
  map_->InsertScan(std::move(points_local), sensor_origin_local);
  ++scans_3d_;
}

RetiredSubmap Submap::Retire() {
  assert(map_ && "Submap::Retire twice");
  RetiredSubmap retired;
  retired.id = id_;
  retired.T_local_submap = T_local_submap_;
  retired.scans_3d = scans_3d_;
  try {
    map_->WaitForUpdates();
  } catch (const std::exception&) {
    // A failed background update already surfaced to the localiser's
    // WaitForUpdates (or is moot now): keep what the octree holds.
  }
  const Eigen::Vector3f origin = T_local_submap_.translation().cast<float>();
  std::vector<Eigen::Vector3f> points = map_->SurfaceMeans();
  retired.update_times = map_->UpdateTimes();
  for (Eigen::Vector3f& p : points) p -= origin;
  retired.points_submap = CompactPoints(points);
  map_.reset();
  return retired;
}

}  // namespace unimap::map
