#pragma once
#include <cstddef>

#include <Eigen/Core>

namespace unimap::map {

// Axis-aligned box of octree voxels in key coordinates (integers, min and max
// both inclusive). Empty when any min exceeds its max.
class KeyBox {
 public:
  // The empty box.
  KeyBox();
  KeyBox(const Eigen::Vector3i& min_key, const Eigen::Vector3i& max_key);

  bool IsEmpty() const { return (min_.array() > max_.array()).any(); }
  const Eigen::Vector3i& min() const { return min_; }
  const Eigen::Vector3i& max() const { return max_; }
  // Voxels per axis (zero for an empty box).
  Eigen::Vector3i Dims() const;
  std::size_t CellCount() const;

  bool Contains(const Eigen::Vector3i& key) const;
  // True when other is empty or lies inside this box.
  bool Contains(const KeyBox& other) const;
  // Grows the box to include key / other.
  void Extend(const Eigen::Vector3i& key);
  void Extend(const KeyBox& other);
  // The box grown by cells voxels on every side (empty stays empty).
  KeyBox Inflated(int cells) const;
  KeyBox Intersection(const KeyBox& other) const;

  bool operator==(const KeyBox& other) const;
  bool operator!=(const KeyBox& other) const { return !(*this == other); }

 private:
  Eigen::Vector3i min_;
  Eigen::Vector3i max_;
};

}  // namespace unimap::map
