#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include <tsl/robin_map.h>
#include <Eigen/Core>

namespace unimap::map {

// Where the surface lies inside each occupied voxel. Per voxel it keeps a
// running average of the returns that fell in it (plain up to kMaxWeight
// returns, then exponential with weight 1 / kMaxWeight, so later returns
// still move it): their mean, their scatter and the mean unit vector towards
// the sensor. Refresh derives the voxel's surface element: a disk of radius
// kPatchRadius (voxels) about the voxel's mean, in the plane fitted to the
// returns of the voxel and its 26 neighbours (smallest principal axis of
// their pooled scatter: a 3-voxel patch, so voxels the surface only clips
// and noisy returns still get a normal), oriented towards the side the
// sensor saw (a lone scan line gets the normal across it closest to the
// view direction); or only the mean point when the pooled returns span no
// plane (corners, rough or two-sided surfaces).
// SignedDistance measures to that element, negative directly behind an
// oriented disk (when signed), so interpolating the distances of cells on
// both sides of a surface crosses zero on it. Voxels are named by packed
// octree keys (Pack). Not thread-safe.
class SurfacePoints {
 public:
  // Surface of one voxel (map frame).
  struct Element {
    Eigen::Vector3f mean_m = Eigen::Vector3f::Zero();  // mean of the voxel's returns
    Eigen::Vector3f normal = Eigen::Vector3f::Zero();  // unit plane normal when planar
    bool planar = false;                               // the returns span a plane: distances are to the disk
    bool oriented = false;                             // normal points to the side the sensor saw the surface from
    float scale = 1.0f;                                // cell edge in voxels the returns came from (1, or
                                                       // DistanceMapOptions' coarse cells): scales the disk
  };

  // Returns counted in full before the average becomes exponential.
  static constexpr float kMaxWeight = 50.0f;
  // Disk radius (voxels): a cell's nearest voxel centre may belong to a voxel
  // whose mean lies up to ~1.5 voxels sideways on a tilted surface. Surfaces
  // thus reach up to about a voxel beyond their real edges.
  static constexpr float kPatchRadius = 1.5f;
  // Fraction of a voxel's weight in new returns that triggers a new plane fit.
  static constexpr float kRefitFraction = 0.5f;

  // signed_distances false: SignedDistance returns magnitudes only.
  // patch_radius_voxels: the disk's radius (kPatchRadius by default).
  explicit SurfacePoints(double resolution_m, bool signed_distances = true, float patch_radius_voxels = kPatchRadius);

  // Hash of packed keys for power-of-two tables: they are structured (x, y,
  // z in 16-bit fields), so they are mixed first (MurmurHash3's finaliser).
  struct KeyHash {
    std::size_t operator()(std::uint64_t key) const {
      key ^= key >> 33;
      key *= 0xff51afd7ed558ccdull;
      key ^= key >> 33;
      key *= 0xc4ceb9fe1a85ec53ull;
      key ^= key >> 33;
      return static_cast<std::size_t>(key);
    }
  };

  // The packed form of a 16-bit octree key (x, y, z).
  static std::uint64_t Pack(const Eigen::Vector3i& key) {
    return (static_cast<std::uint64_t>(key.x() & 0xffff) << 32) | (static_cast<std::uint64_t>(key.y() & 0xffff) << 16) |
           static_cast<std::uint64_t>(key.z() & 0xffff);
  }

  // Where a voxel's entry is kept: valid until its key is erased.
  using Slot = std::uint32_t;
  // Adds the return p_map to the voxel key whose centre is voxel_center_map.
  // sensor_map (null when unknown, e.g. prior point clouds) orients the plane.
  // scale > 1: the return stands for a cell of scale^3 voxels centred on the
  // voxel (it may lie up to scale / 2 voxels from its centre); the element's
  // disk then reaches scale times as far (Element::scale, the largest given).
  // The voxel's element changes only on Refresh. Returns the voxel's slot.
  Slot Add(std::uint64_t key, const Eigen::Vector3f& voxel_center_map, const Eigen::Vector3f& p_map,
           const Eigen::Vector3f* sensor_map, float scale = 1.0f);
  // Updates the element of key: its mean always; its plane (fitted to its
  // and its neighbours' returns) when none was fitted yet or the voxel got
  // kRefitFraction of its weight (a full kMaxWeight once the average is
  // exponential) in new returns since (no-op for unknown keys). Call it
  // after the Adds of a whole scan. Returns Find(key) (saves its look-up).
  const Element* Refresh(std::uint64_t key, const Eigen::Vector3f& voxel_center_map);
  // Refresh of key, whose slot Add returned since key was last erased (no look-up).
  const Element* Refresh(Slot slot, std::uint64_t key, const Eigen::Vector3f& voxel_center_map);
  // Forgets key (its voxel became free).
  void Erase(std::uint64_t key);
  // The element of key (as of its last Refresh), or null when the voxel has
  // none (no return, or not refreshed since its first). The pointer stays
  // valid, following the element's later refreshes, until key is erased.
  const Element* Find(std::uint64_t key) const;

  // Distance from p_map to the element, negative directly behind an
  // oriented disk when signed: the disk (planar) or the mean point (not planar).
  // Inline: the export calls it for every cell near a surface.
  float SignedDistance(const Element& element, const Eigen::Vector3f& p_map) const {
    const Eigen::Vector3f r = p_map - element.mean_m;
    if (!element.planar) return r.norm();
    // Distance to a disk: |height| above it, sqrt(height^2 + (lateral - radius)^2) beside it.
    const float height = r.dot(element.normal);
    const float lateral_sq = std::max(0.0f, r.squaredNorm() - height * height);
    if (lateral_sq <= patch_radius_sq_m2_ * element.scale * element.scale) {
      return signed_ && element.oriented && height < 0.0f ? height : std::abs(height);  // negative behind
    }
    const float outside = std::sqrt(lateral_sq) - patch_radius_m_ * element.scale;
    return std::sqrt(height * height + outside * outside);
  }

  // Calls visit(key, element) for every voxel with an element.
  void ForEach(const std::function<void(std::uint64_t, const Element&)>& visit) const;

  std::size_t size() const { return index_.size(); }
  // Approximate heap memory of the table (bytes).
  std::size_t MemoryBytes() const;

 private:
  // Running moments of one voxel's returns, relative to the voxel centre
  // (small numbers, so float keeps sub-millimetre precision anywhere).
  struct Entry {
    float weight = 0.0f;                                                     // returns counted (<= kMaxWeight)
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();                           // sum of offsets
    Eigen::Matrix<float, 6, 1> sum_sq = Eigen::Matrix<float, 6, 1>::Zero();  // xx xy xz yy yz zz
    Eigen::Vector3f sum_view = Eigen::Vector3f::Zero();                      // sum of unit vectors to the sensor
    float adds_since_fit = 0.0f;                                             // returns added since the plane fit
    float scale = 1.0f;                                                      // largest scale given to Add
    bool has_element = false;                                                // element is valid
    Element element;
  };

  // Moments of key and its neighbours step voxels away, relative to key's voxel centre.
  Entry PooledMoments(std::uint64_t key, int step) const;

  float resolution_m_;
  bool signed_;               // SignedDistance is negative behind oriented disks
  float patch_radius_m_;      // the disk's radius (m)
  float patch_radius_sq_m2_;  // its square
  // Entries live in a deque (stable addresses: Find's pointers stay valid)
  // indexed by an open-addressing table (a plane fit looks up 27 keys).
  Entry* Lookup(std::uint64_t key);
  const Entry* Lookup(std::uint64_t key) const;
  tsl::robin_map<std::uint64_t, std::uint32_t, KeyHash> index_;
  std::deque<Entry> store_;
  std::vector<std::uint32_t> free_;  // store_ slots of erased entries
  // Add's last key and its slot: consecutive returns of a scan often share
  // a voxel, which then costs no hash look-up.
  std::uint64_t last_key_ = ~std::uint64_t{0};
  std::uint32_t last_slot_ = 0;

  // Refresh of the entry of key.
  const Element* RefreshEntry(Entry* entry, std::uint64_t key, const Eigen::Vector3f& voxel_center_map);
};

}  // namespace unimap::map
