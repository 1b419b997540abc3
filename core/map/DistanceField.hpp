#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::map {

// Immutable snapshot of the distance map for lookups: a dense grid over an
// axis-aligned box, aligned with the octree voxels, holding for every voxel
// the distance from its centre to the nearest occupied voxel centre, clamped
// at clamp(). Distances are stored as 16-bit steps of clamp() / 65535.
// Anything outside the box (and NaN) reads clamp(). Safe to share between
// threads: nothing changes after construction.
class DistanceField {
 public:
  // Largest quantised value; stands for clamp().
  static constexpr std::uint16_t kMaxSteps = 65535;

  // An empty field: every lookup returns clamp_m.
  explicit DistanceField(float clamp_m, std::uint64_t sequence = 0);
  // A field over the box [origin_m, origin_m + dims * resolution_m) with
  // cells[(ix * dims.y() + iy) * dims.z() + iz] = Quantise(distance of cell).
  // Throws unimap::InputError when the sizes disagree or a value is invalid.
  DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims, float resolution_m,
                float clamp_m, std::vector<std::uint16_t> cells, std::uint64_t sequence);

  // The 16-bit code of a distance (values >= clamp_m map to kMaxSteps).
  static std::uint16_t Quantise(float distance_m, float clamp_m);

  // Distance (m) of the voxel containing p_map; clamp() outside the box.
  // One floor per axis, one index, one load.
  float Distance(const Eigen::Vector3f& p_map) const {
    const float fx = (p_map.x() - origin_m_.x()) * inv_resolution_;
    const float fy = (p_map.y() - origin_m_.y()) * inv_resolution_;
    const float fz = (p_map.z() - origin_m_.z()) * inv_resolution_;
    if (!(fx >= 0.0f && fy >= 0.0f && fz >= 0.0f && fx < dims_f_.x() && fy < dims_f_.y() &&
          fz < dims_f_.z())) {
      return clamp_m_;
    }
    const std::size_t index = static_cast<std::size_t>(static_cast<int>(fx)) * stride_x_ +
                              static_cast<std::size_t>(static_cast<int>(fy)) * stride_y_ +
                              static_cast<std::size_t>(static_cast<int>(fz));
    return static_cast<float>(cells_[index]) * step_m_;
  }

  // Trilinear interpolation between voxel centres (cells outside the box
  // count as clamp()); *gradient_map (if not null) receives its gradient.
  float DistanceTrilinear(const Eigen::Vector3f& p_map, Eigen::Vector3f* gradient_map) const;

  // Distance (m) stored for a cell; clamp() when the cell is outside the grid.
  float CellDistance(const Eigen::Vector3i& cell) const;
  // Centre of a cell in the map frame.
  Eigen::Vector3f CellCentre(const Eigen::Vector3i& cell) const;
  // True when p_map lies inside the box.
  bool Contains(const Eigen::Vector3f& p_map) const;

  const Eigen::Vector3f& origin() const { return origin_m_; }  // box min corner (m)
  Eigen::Vector3f box_max() const;                            // box max corner (m)
  const Eigen::Vector3i& dims() const { return dims_; }        // cells per axis
  float resolution() const { return resolution_m_; }           // cell edge (m)
  float clamp() const { return clamp_m_; }                     // clamp distance (m)
  std::uint64_t sequence() const { return sequence_; }         // updates integrated
  std::size_t CellCount() const { return cells_.size(); }
  std::size_t MemoryBytes() const { return cells_.size() * sizeof(std::uint16_t); }

 private:
  Eigen::Vector3f origin_m_ = Eigen::Vector3f::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  Eigen::Vector3f dims_f_ = Eigen::Vector3f::Zero();  // dims_ as float, for the bounds test
  float resolution_m_ = 1.0f;
  float inv_resolution_ = 1.0f;
  float clamp_m_ = 0.0f;
  float step_m_ = 0.0f;  // metres per quantisation step
  std::size_t stride_x_ = 0;
  std::size_t stride_y_ = 0;
  std::vector<std::uint16_t> cells_;
  std::uint64_t sequence_ = 0;
};

}  // namespace unimap::map
