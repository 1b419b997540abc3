#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::map {

// Points stored at half the size of Eigen::Vector3f: each coordinate as a
// 16-bit integer times one scale per set (the largest coordinate / 32767, at
// least kMinStep), so a point comes back within scale / 2 of where it was
// (0.9 mm for a set spanning +-60 m). For what is kept long and read rarely
// (retired submaps' surfaces, read when a loop-closure matcher is built).
class CompactPoints {
 public:
  // The finest step (m): sets within +-3.3 m keep 0.1 mm.
  static constexpr float kMinStep = 1e-4f;

  CompactPoints() = default;
  // Non-finite points are not expected (surface means); they are stored as 0.
  explicit CompactPoints(const std::vector<Eigen::Vector3f>& points);

  std::vector<Eigen::Vector3f> Expand() const;
  std::size_t size() const { return coordinates_.size() / 3; }
  bool empty() const { return coordinates_.empty(); }
  float step() const { return step_; }
  // Bytes held by the coordinates.
  std::size_t bytes() const { return coordinates_.capacity() * sizeof(std::int16_t); }

 private:
  float step_ = kMinStep;
  std::vector<std::int16_t> coordinates_;  // x, y, z per point
};

}  // namespace unimap::map
