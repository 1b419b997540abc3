#include "map/EdtRegion.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <dynamicEDT3D/dynamicEDTOctomap.h>
#include <octomap/OcTree.h>

#include "unimap/Errors.hpp"

namespace unimap::map {

namespace {

octomap::OcTreeKey ToOctreeKey(const Eigen::Vector3i& key) {
  return octomap::OcTreeKey(static_cast<octomap::key_type>(key.x()), static_cast<octomap::key_type>(key.y()),
                            static_cast<octomap::key_type>(key.z()));
}

}  // namespace

EdtRegion::EdtRegion(octomap::OcTree* tree, const KeyBox& box, float clamp_m)
    : tree_(tree), box_(box), clamp_m_(clamp_m) {
  if (tree_ == nullptr || box_.IsEmpty()) throw InputError("EdtRegion: needs a tree and a box");
  tree_->resetChangeDetection();
  const octomap::point3d min_center = tree_->keyToCoord(ToOctreeKey(box_.min()));
  const octomap::point3d max_center = tree_->keyToCoord(ToOctreeKey(box_.max()));
  // One voxel beyond the clamp so every distance up to clamp_m is exact.
  const float max_distance_m = clamp_m_ + static_cast<float>(tree_->getResolution());
  edt_ = std::make_unique<DynamicEDTOctomap>(max_distance_m, tree_, min_center, max_center,
                                             /*treatUnknownAsOccupied=*/false);
  edt_->update(/*updateRealDist=*/true);
}

EdtRegion::~EdtRegion() = default;

void EdtRegion::Update() { edt_->update(/*updateRealDist=*/true); }

std::shared_ptr<const DistanceField> EdtRegion::Export(std::uint64_t sequence, const SurfacePoints* surfaces,
                                                       bool with_planes) const {
  const Eigen::Vector3i dims = box_.Dims();
  std::vector<std::uint16_t> cells(box_.CellCount());
  const double half_voxel_m = 0.5 * tree_->getResolution();
  const octomap::point3d min_center = tree_->keyToCoord(ToOctreeKey(box_.min()));
  const Eigen::Vector3f origin_m(static_cast<float>(min_center.x() - half_voxel_m),
                                 static_cast<float>(min_center.y() - half_voxel_m),
                                 static_cast<float>(min_center.z() - half_voxel_m));
  const auto make_field = [&](DistanceField::Encoding encoding) {
    return std::make_shared<DistanceField>(origin_m, dims, static_cast<float>(tree_->getResolution()), clamp_m_,
                                           std::move(cells), sequence, encoding);
  };
  std::size_t index = 0;
  if (surfaces == nullptr) {
    for (int x = box_.min().x(); x <= box_.max().x(); ++x) {
      for (int y = box_.min().y(); y <= box_.max().y(); ++y) {
        for (int z = box_.min().z(); z <= box_.max().z(); ++z) {
          const float distance_m = edt_->getDistance_unsafe(ToOctreeKey(Eigen::Vector3i(x, y, z)));
          cells[index++] = DistanceField::Quantise(distance_m, clamp_m_);
        }
      }
    }
    return make_field(DistanceField::Encoding::kUnsigned);
  }
  CellPlanes planes(with_planes ? cells.size() : 0);
  FillSigned(*surfaces, &cells, with_planes ? &planes : nullptr);
  std::shared_ptr<DistanceField> field = make_field(DistanceField::Encoding::kSigned);
  if (with_planes) field->SetPlanes(std::move(planes));
  return field;
}

void EdtRegion::FillSigned(const SurfacePoints& surfaces, std::vector<std::uint16_t>* cells, CellPlanes* planes) const {
  // Neighbouring cells mostly share their nearest obstacle. Remember the
  // obstacle (and its element) of each cell of the current x plane, so the
  // cells just visited along z, y and x are checked first, then a small
  // cache of recent obstacles, before the surface table: the plane and the
  // cache stay in the CPU cache, the table (all voxels ever hit) does not.
  struct Seen {
    std::uint64_t key = ~std::uint64_t{0};
    const SurfacePoints::Element* element = nullptr;
  };
  constexpr int kRecentBits = 12;
  std::vector<Seen> recent(std::size_t{1} << kRecentBits);
  const Eigen::Vector3i dims = box_.Dims();
  std::vector<Seen> plane(static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(dims.z()));
  const auto element_of = [&](std::uint64_t key, std::size_t in_plane, bool has_z, bool has_y) {
    if (has_z && plane[in_plane - 1].key == key) return plane[in_plane - 1].element;
    const std::size_t below_y = in_plane - static_cast<std::size_t>(dims.z());
    if (has_y && plane[below_y].key == key) return plane[below_y].element;
    if (plane[in_plane].key == key) return plane[in_plane].element;  // x - 1
    Seen& slot = recent[(key * 0x9E3779B97F4A7C15ull) >> (64 - kRecentBits)];
    if (slot.key != key) slot = Seen{key, surfaces.Find(key)};
    return slot.element;
  };
  // The transform's closest obstacles, in its cell coordinates (key - box
  // min). DynamicEDTOctomap inherits DynamicEDT3D privately and only offers
  // them through float coordinates (four conversions per cell); an explicit
  // cast to an inaccessible base is well-defined ([expr.cast]/4).
  const DynamicEDT3D& cells_edt = (const DynamicEDT3D&)(*edt_);
  const float resolution_m = static_cast<float>(tree_->getResolution());
  const Eigen::Vector3f min_center =
      Eigen::Vector3f(static_cast<float>(tree_->keyToCoord(static_cast<octomap::key_type>(box_.min().x()))),
                      static_cast<float>(tree_->keyToCoord(static_cast<octomap::key_type>(box_.min().y()))),
                      static_cast<float>(tree_->keyToCoord(static_cast<octomap::key_type>(box_.min().z()))));
  // Cells at the transform's maximum distance have no obstacle in reach.
  const float reach_m = edt_->getMaxDist();
  std::size_t index = 0;
  for (int x = 0; x < dims.x(); ++x) {
    std::size_t in_plane = 0;  // (y, z) of the current cell; plane[] holds x - 1 from here on
    for (int y = 0; y < dims.y(); ++y) {
      for (int z = 0; z < dims.z(); ++z, ++in_plane) {
        const Eigen::Vector3i cell(x, y, z);
        float distance_m = edt_->getDistance_unsafe(ToOctreeKey(box_.min() + cell));
        Seen seen;
        if (distance_m < reach_m) {
          const INTPOINT3D obstacle = cells_edt.getClosestObstacle(x, y, z);
          if (obstacle.x != DynamicEDT3D::invalidObstData) {
            seen.key = SurfacePoints::Pack(box_.min() + Eigen::Vector3i(obstacle.x, obstacle.y, obstacle.z));
            seen.element = element_of(seen.key, in_plane, z > 0, y > 0);
            if (seen.element != nullptr) {
              const Eigen::Vector3f center = min_center + cell.cast<float>() * resolution_m;
              distance_m = surfaces.SignedDistance(*seen.element, center);
              if (planes != nullptr && seen.element->planar) {
                planes->Set(index, seen.element->normal, seen.element->normal.dot(center - seen.element->mean_m));
              }
            }
          }
        }
        plane[in_plane] = seen;
        (*cells)[index++] = DistanceField::QuantiseSigned(distance_m, clamp_m_);
      }
    }
  }
}

}  // namespace unimap::map
