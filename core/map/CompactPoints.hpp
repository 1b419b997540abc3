#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::map {

// Points stored for the long term in a fraction of Eigen::Vector3f's size:
// each coordinate as a 16-bit integer times one scale per set (the largest
// coordinate / 32767, at least kMinStep), so a point comes back within
// scale / 2 of where it was (0.9 mm for a set spanning +-60 m); then the
// integers, per axis as differences from the previous point's (byte planes:
// low bytes, then high bytes), deflated (zlib). Lossless after the
// quantisation: Expand gives the same points in the same order every time.
// For what is kept long and read rarely (retired submaps' surfaces, read
// when a loop-closure matcher is built).
class CompactPoints {
 public:
  // The finest step (m): sets within +-3.3 m keep 0.1 mm.
  static constexpr float kMinStep = 1e-4f;

  CompactPoints() = default;
  // Non-finite points are not expected (surface means); they are stored as 0.
  explicit CompactPoints(const std::vector<Eigen::Vector3f>& points);

  std::vector<Eigen::Vector3f> Expand() const;
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  float step() const { return step_; }
  // Bytes held (the deflated coordinates).
  std::size_t bytes() const { return packed_.capacity(); }

 private:
  float step_ = kMinStep;
  std::size_t size_ = 0;               // points
  std::vector<unsigned char> packed_;  // deflated byte planes of the coordinate differences
};

}  // namespace unimap::map
