// DistanceMap's prior maps: from an octree, an OctoMap .bt file or a point
// cloud (the rest of the class is in DistanceMap.cpp).
#include <string>
#include <system_error>
#include <utility>

#include <octomap/OcTree.h>

#include "map/DistanceMap.hpp"
#include "map/OccupancyTree.hpp"
#include "unimap/Errors.hpp"

namespace unimap::map {

std::unique_ptr<DistanceMap> DistanceMap::FromOctree(std::unique_ptr<octomap::OcTree> tree,
                                                     const DistanceMapOptions& options,
                                                     const Eigen::Vector3f& center_map) {
  if (tree == nullptr) throw InputError("DistanceMap::FromOctree: null octree");
  const DistanceMapOptions valid = ValidOptions(options, tree->getResolution());
  auto occupancy = std::make_unique<OccupancyTree>(std::move(tree), valid);
  std::unique_ptr<DistanceMap> map(new DistanceMap(std::move(occupancy), valid));
  map->SetCenter(center_map);
  return map;
}

std::unique_ptr<DistanceMap> DistanceMap::LoadBt(const std::filesystem::path& path, const DistanceMapOptions& options,
                                                 const Eigen::Vector3f& center_map) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError("cannot read octree '" + path.string() + "': no such file");
  }
  auto tree = std::make_unique<octomap::OcTree>(0.1);  // readBinary sets the file's resolution
  if (!tree->readBinary(path.string())) {
    throw InputError("cannot read octree '" + path.string() + "': not a valid OctoMap .bt file");
  }
  return FromOctree(std::move(tree), options, center_map);
}

std::unique_ptr<DistanceMap> DistanceMap::FromPoints(const std::vector<Eigen::Vector3f>& points_map,
                                                     const DistanceMapOptions& options,
                                                     const Eigen::Vector3f& center_map) {
  const DistanceMapOptions valid = ValidOptions(options, options.resolution_m);
  auto occupancy = std::make_unique<OccupancyTree>(valid);
  occupancy->MarkOccupied(points_map);
  std::unique_ptr<DistanceMap> map(new DistanceMap(std::move(occupancy), valid));
  map->SetCenter(center_map);
  return map;
}

}  // namespace unimap::map
