#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "map/DistanceField.hpp"
#include "map/KeyBox.hpp"
#include "map/SurfacePoints.hpp"

namespace octomap {
class OcTree;
}
template <class TREE>
class DynamicEDTOctomapBase;

namespace unimap::map {

// The incremental Euclidean distance transform (DynamicEDT3D, via its OctoMap
// adaptor) over one box of octree voxels. It consumes the octree's change
// detection: every Update() applies the keys changed since the previous one.
// Not thread-safe; the owner serialises access together with the tree.
class EdtRegion {
 public:
  // Builds the transform over box from the tree's current occupancy (any
  // pending change keys are discarded first, they are already in the tree)
  // and computes all distances, exact up to clamp_m. box must not be empty.
  EdtRegion(octomap::OcTree* tree, const KeyBox& box, float clamp_m);
  ~EdtRegion();
  EdtRegion(const EdtRegion&) = delete;
  EdtRegion& operator=(const EdtRegion&) = delete;

  // Applies the voxels whose occupancy changed since the last call (changes
  // outside the box are ignored) and repairs the distances around them.
  void Update();
  // Copies the box into a new immutable field tagged with sequence. Without
  // surfaces, each cell holds the distance from its centre to the nearest
  // occupied voxel centre (kUnsigned). With them (kSigned), cells whose
  // nearest occupied voxel (by centre, as the transform finds it) has a
  // surface element hold the signed distance to that element instead
  // (SurfacePoints::SignedDistance); the others keep the centre distance.
  // With surfaces and with_planes the field also carries the plane of each
  // cell's nearest planar element (DistanceField::SetPlanes).
  std::shared_ptr<const DistanceField> Export(std::uint64_t sequence, const SurfacePoints* surfaces = nullptr,
                                              bool with_planes = false) const;

  const KeyBox& box() const { return box_; }
  std::size_t CellCount() const { return box_.CellCount(); }

 private:
  // Export's cells with surfaces (kSigned codes, in the box's x-y-z order).
  // planes (if not null) receives the plane of each cell's nearest planar element.
  void FillSigned(const SurfacePoints& surfaces, std::vector<std::uint16_t>* cells, CellPlanes* planes) const;

  octomap::OcTree* tree_;
  KeyBox box_;
  float clamp_m_;
  std::unique_ptr<DynamicEDTOctomapBase<octomap::OcTree>> edt_;
};

}  // namespace unimap::map
