#include "map/EdtRegion.hpp"

#include <vector>

#include <dynamicEDT3D/dynamicEDTOctomap.h>
#include <octomap/OcTree.h>

#include "unimap/Errors.hpp"

namespace unimap::map {

namespace {

octomap::OcTreeKey ToOctreeKey(const Eigen::Vector3i& key) {
  return octomap::OcTreeKey(static_cast<octomap::key_type>(key.x()),
                            static_cast<octomap::key_type>(key.y()),
                            static_cast<octomap::key_type>(key.z()));
}

}  // namespace

EdtRegion::EdtRegion(octomap::OcTree* tree, const KeyBox& box, float clamp_m)
    : tree_(tree), box_(box), clamp_m_(clamp_m) {
  if (tree_ == nullptr || box_.IsEmpty()) throw InputError("EdtRegion: needs a tree and a box");
  tree_->resetChangeDetection();
  const octomap::point3d min_centre = tree_->keyToCoord(ToOctreeKey(box_.min()));
  const octomap::point3d max_centre = tree_->keyToCoord(ToOctreeKey(box_.max()));
  // One voxel beyond the clamp so every distance up to clamp_m is exact.
  const float max_distance_m = clamp_m_ + static_cast<float>(tree_->getResolution());
  edt_ = std::make_unique<DynamicEDTOctomap>(max_distance_m, tree_, min_centre, max_centre,
                                             /*treatUnknownAsOccupied=*/false);
  edt_->update(/*updateRealDist=*/true);
}

EdtRegion::~EdtRegion() = default;

void EdtRegion::Update() { edt_->update(/*updateRealDist=*/true); }

std::shared_ptr<const DistanceField> EdtRegion::Export(std::uint64_t sequence) const {
  const Eigen::Vector3i dims = box_.Dims();
  std::vector<std::uint16_t> cells(box_.CellCount());
  std::size_t index = 0;
  for (int x = box_.min().x(); x <= box_.max().x(); ++x) {
    for (int y = box_.min().y(); y <= box_.max().y(); ++y) {
      for (int z = box_.min().z(); z <= box_.max().z(); ++z) {
        const float distance_m = edt_->getDistance_unsafe(ToOctreeKey(Eigen::Vector3i(x, y, z)));
        cells[index++] = DistanceField::Quantise(distance_m, clamp_m_);
      }
    }
  }
  const double half_voxel_m = 0.5 * tree_->getResolution();
  const octomap::point3d min_centre = tree_->keyToCoord(ToOctreeKey(box_.min()));
  const Eigen::Vector3f origin_m(static_cast<float>(min_centre.x() - half_voxel_m),
                                 static_cast<float>(min_centre.y() - half_voxel_m),
                                 static_cast<float>(min_centre.z() - half_voxel_m));
  return std::make_shared<const DistanceField>(origin_m, dims,
                                               static_cast<float>(tree_->getResolution()),
                                               clamp_m_, std::move(cells), sequence);
}

}  // namespace unimap::map
