#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::map {

// The plane of each distance-field cell's nearest surface element (see
// SurfacePoints): a unit normal and the signed height of the cell's centre
// above the plane, or none (no element in reach, or one that spans no
// plane). Scan matching ties a point to the plane of the cell it falls in
// once, at the predicted pose, and then measures it against that plane
// (point to plane, as in ICP), so that a point on a surface the map has
// only partly seen is not pulled sideways towards the edge of what it has
// seen. Cells share the DistanceField's grid (same order, origin and
// resolution). 4 bytes per cell: the normal in octahedral coordinates (8
// bits each) and the height in steps of kHeightStepM (int16, kNone: no
// plane). Immutable once shared.
class CellPlanes {
 public:
  // Height quantum (m): 0.1 mm, heights within +-3.2 m.
  static constexpr float kHeightStepM = 1e-4f;

  CellPlanes() = default;
  // All cells of a grid of cell_count cells without a plane.
  explicit CellPlanes(std::size_t cell_count);

  // Sets cell index's plane: unit normal and the signed height of the cell
  // centre above it (clamped to the representable range).
  void Set(std::size_t index, const Eigen::Vector3f& normal, float center_height_m);
  // Cell index's plane; false when it has none.
  bool Get(std::size_t index, Eigen::Vector3f* normal, float* center_height_m) const;

  std::size_t size() const { return cells_.size(); }
  std::size_t MemoryBytes() const { return cells_.size() * sizeof(std::uint32_t); }

 private:
  std::vector<std::uint32_t> cells_;  // normal code << 16 | height code
};

}  // namespace unimap::map
