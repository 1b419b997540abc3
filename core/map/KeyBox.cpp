#include "map/KeyBox.hpp"

#include <limits>

namespace unimap::map {

KeyBox::KeyBox()
    : min_(Eigen::Vector3i::Constant(std::numeric_limits<int>::max())),
      max_(Eigen::Vector3i::Constant(std::numeric_limits<int>::min())) {}

KeyBox::KeyBox(const Eigen::Vector3i& min_key, const Eigen::Vector3i& max_key) : min_(min_key), max_(max_key) {
  if (IsEmpty()) *this = KeyBox();
}

Eigen::Vector3i KeyBox::Dims() const {
  if (IsEmpty()) return Eigen::Vector3i::Zero();
  return max_ - min_ + Eigen::Vector3i::Ones();
}

std::size_t KeyBox::CellCount() const {
  const Eigen::Vector3i dims = Dims();
  return static_cast<std::size_t>(dims.x()) * static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(dims.z());
}

bool KeyBox::Contains(const Eigen::Vector3i& key) const {
  return (key.array() >= min_.array()).all() && (key.array() <= max_.array()).all();
}

bool KeyBox::Contains(const KeyBox& other) const {
  if (other.IsEmpty()) return true;
  return Contains(other.min_) && Contains(other.max_);
}

void KeyBox::Extend(const Eigen::Vector3i& key) {
  min_ = min_.cwiseMin(key);
  max_ = max_.cwiseMax(key);
}

void KeyBox::Extend(const KeyBox& other) {
  if (other.IsEmpty()) return;
  Extend(other.min_);
  Extend(other.max_);
}

KeyBox KeyBox::Inflated(int cells) const {
  if (IsEmpty()) return *this;
  return KeyBox(min_ - Eigen::Vector3i::Constant(cells), max_ + Eigen::Vector3i::Constant(cells));
}

KeyBox KeyBox::Intersection(const KeyBox& other) const {
  if (IsEmpty() || other.IsEmpty()) return KeyBox();
  return KeyBox(min_.cwiseMax(other.min_), max_.cwiseMin(other.max_));
}

bool KeyBox::operator==(const KeyBox& other) const {
  if (IsEmpty() || other.IsEmpty()) return IsEmpty() == other.IsEmpty();
  return min_ == other.min_ && max_ == other.max_;
}

}  // namespace unimap::map
