#include "World.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace unimap::sim {

// One BVH node: padded bounds plus either two children or a primitive range.
struct World::Node {
  double lo[3];        // bounds minimum corner (padded)
  double hi[3];        // bounds maximum corner (padded)
  int right_or_first;  // interior: index of the right child (the left is this + 1); leaf: first slot in ordered_
  int count;           // leaf: number of primitives (>= 1); interior: 0
};

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// SAH cost of one node visit relative to one primitive intersection.
constexpr double kTraversalCost = 0.5;
// Largest leaf the SAH may prefer over a split; larger ranges are always split.
constexpr int kMaxLeafSize = 4;
// Below this depth splits fall back to object medians, so the tree depth stays
// under kSahDepthLimit + log2(n) + 1 and fits the traversal stack.
constexpr int kSahDepthLimit = 32;
constexpr int kStackSize = 96;
// Bounds are padded by this (plus a relative part) so rounding in the slab
// test cannot reject a surface lying on a box face (flat planes have none).
constexpr double kBoundsPadM = 1e-7;

// Entry range of the ray into a node's box, clipped to [t_min, t_max]; false
// when the clipped interval is empty (slab test, Kay & Kajiya 1986).
inline bool SlabEntry(const double* lo, const double* hi, const double* origin, const double* inv_direction,
                      double t_min, double t_max, double* t_entry) {
  for (int i = 0; i < 3; ++i) {
    // Branch-free (min/max): the products are never NaN (see Cast).
    const double t0 = (lo[i] - origin[i]) * inv_direction[i];
    const double t1 = (hi[i] - origin[i]) * inv_direction[i];
    t_min = std::max(t_min, std::min(t0, t1));
    t_max = std::min(t_max, std::max(t0, t1));
  }
  *t_entry = t_min;
  return t_min <= t_max;
}

// Squared distance from p to a box (0 inside).
inline double BoxDistanceSquared(const double* lo, const double* hi, const Eigen::Vector3d& p) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double below = lo[i] - p[i];
    const double above = p[i] - hi[i];
    const double out = below > 0.0 ? below : (above > 0.0 ? above : 0.0);
    sum += out * out;
  }
  return sum;
}

// Surface area of a box (0 for an empty one).
double SurfaceArea(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return 0.0;
  const Eigen::Vector3d s = box.sizes();
  return 2.0 * (s.x() * s.y() + s.y() * s.z() + s.z() * s.x());
}

}  // namespace

World::World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;
World::~World() = default;

void World::Add(std::unique_ptr<Primitive> primitive) {
  if (!primitive) throw std::invalid_argument("World::Add: null primitive");
  primitives_.push_back(std::move(primitive));
  built_ = false;
}

void World::Build() {
  const int n = static_cast<int>(primitives_.size());
  std::vector<Eigen::AlignedBox3d> bounds;
  bounds.reserve(primitives_.size());
  for (const auto& primitive : primitives_) {
    Eigen::AlignedBox3d box = primitive->Bounds();
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) {
      throw std::invalid_argument("World::Build: a " + primitive->Kind() + " primitive has empty or non-finite bounds");
    }
    const Eigen::Vector3d pad =
        Eigen::Vector3d::Constant(kBoundsPadM) + 1e-12 * box.min().cwiseAbs().cwiseMax(box.max().cwiseAbs());
    bounds.emplace_back(box.min() - pad, box.max() + pad);
  }
  nodes_.clear();
  nodes_.reserve(primitives_.size() * 2);
  ordered_.resize(primitives_.size());
  std::iota(ordered_.begin(), ordered_.end(), 0);
  if (n > 0) BuildNode(0, n, 0, bounds);
  ordered_primitives_.clear();
  for (const int i : ordered_) ordered_primitives_.push_back(primitives_[i].get());
  built_ = true;
}

int World::BuildNode(int begin, int end, int depth, const std::vector<Eigen::AlignedBox3d>& bounds) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  Eigen::AlignedBox3d box;
  for (int i = begin; i < end; ++i) box.extend(bounds[ordered_[i]]);
  for (int axis = 0; axis < 3; ++axis) {
    nodes_[index].lo[axis] = box.min()[axis];
    nodes_[index].hi[axis] = box.max()[axis];
  }
  const int n = end - begin;
  const auto make_leaf = [&] {
    nodes_[index].right_or_first = begin;
    nodes_[index].count = n;
    return index;
  };
  if (n == 1) return make_leaf();

  const auto by_centroid = [&bounds](int axis) {
    return [&bounds, axis](int a, int b) { return bounds[a].center()[axis] < bounds[b].center()[axis]; };
  };
  // Surface area heuristic (MacDonald & Booth 1990), sweeping every split of
  // the centroid-sorted range on each axis:
  //   cost(split) = C_trav + (A_left N_left + A_right N_right) / A_node,  cost(leaf) = N.
  const double area = std::max(SurfaceArea(box), std::numeric_limits<double>::min());
  double best_cost = kInfinity;
  int best_axis = -1;
  int best_count_left = 0;
  if (depth < kSahDepthLimit) {
    std::vector<double> right_area(static_cast<std::size_t>(n));
    for (int axis = 0; axis < 3; ++axis) {
      std::sort(ordered_.begin() + begin, ordered_.begin() + end, by_centroid(axis));
      Eigen::AlignedBox3d right;
      for (int k = n - 1; k >= 1; --k) {
        right.extend(bounds[ordered_[begin + k]]);
        right_area[k] = SurfaceArea(right);
      }
      Eigen::AlignedBox3d left;
      for (int k = 1; k < n; ++k) {  // k primitives on the left
        left.extend(bounds[ordered_[begin + k - 1]]);
        const double cost = kTraversalCost + (SurfaceArea(left) * k + right_area[k] * (n - k)) / area;
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_count_left = k;
        }
      }
    }
    if (n <= kMaxLeafSize && best_cost >= static_cast<double>(n)) return make_leaf();
    std::sort(ordered_.begin() + begin, ordered_.begin() + end, by_centroid(best_axis));
  } else {
    // Object median on the axis of largest centroid spread.
    Eigen::AlignedBox3d centroids;
    for (int i = begin; i < end; ++i) centroids.extend(bounds[ordered_[i]].center());
    Eigen::Index axis = 0;
    centroids.sizes().maxCoeff(&axis);
    best_count_left = n / 2;
    std::nth_element(ordered_.begin() + begin, ordered_.begin() + begin + best_count_left, ordered_.begin() + end,
                     by_centroid(static_cast<int>(axis)));
  }
  const int middle = begin + best_count_left;
  BuildNode(begin, middle, depth + 1, bounds);
  const int right = BuildNode(middle, end, depth + 1, bounds);
  nodes_[index].right_or_first = right;
  nodes_[index].count = 0;
  return index;
}

std::optional<RayHit> World::Cast(const Ray& ray, double min_range_m, double max_range_m) const {
  if (!built_) throw std::logic_error("World::Cast: call Build() after adding primitives");
  if (nodes_.empty() || !(max_range_m > min_range_m)) return std::nullopt;
  const double origin[3] = {ray.origin.x(), ray.origin.y(), ray.origin.z()};
  double inv_direction[3];
  for (int i = 0; i < 3; ++i) {
    // A zero component becomes +-1e-300: its slab products stay finite or
    // infinite, never 0 * inf = NaN.
    const double d = ray.direction[i];
    inv_direction[i] = 1.0 / (std::abs(d) > 1e-300 ? d : std::copysign(1e-300, d));
  }
  struct Entry {
    int node;        // node to visit
    double t_entry;  // range where the ray enters its box
  };
  Entry stack[kStackSize];
  int top = 0;
  double best = max_range_m;
  std::optional<RayHit> nearest;
  double t_root = 0.0;
  if (!SlabEntry(nodes_[0].lo, nodes_[0].hi, origin, inv_direction, min_range_m, best, &t_root)) {
    return std::nullopt;
  }
  stack[top++] = Entry{0, t_root};
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.t_entry > best) continue;  // a nearer hit was found meanwhile
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (int k = node.right_or_first; k < node.right_or_first + node.count; ++k) {
        std::optional<RayHit> hit = ordered_primitives_[k]->Intersect(ray, min_range_m, best);
        if (hit && hit->range_m <= best) {
          best = hit->range_m;
          nearest = hit;
          nearest->primitive_index = ordered_[k];
        }
      }
      continue;
    }
    int near_child = entry.node + 1;
    int far_child = node.right_or_first;
    double t_near = 0.0;
    double t_far = 0.0;
    const bool hit_near =
        SlabEntry(nodes_[near_child].lo, nodes_[near_child].hi, origin, inv_direction, min_range_m, best, &t_near);
    const bool hit_far =
        SlabEntry(nodes_[far_child].lo, nodes_[far_child].hi, origin, inv_direction, min_range_m, best, &t_far);
    if (hit_near && hit_far) {
      if (t_far < t_near) {
        std::swap(near_child, far_child);
        std::swap(t_near, t_far);
      }
      stack[top++] = Entry{far_child, t_far};  // popped after the nearer subtree
      stack[top++] = Entry{near_child, t_near};
    } else if (hit_near) {
      stack[top++] = Entry{near_child, t_near};
    } else if (hit_far) {
      stack[top++] = Entry{far_child, t_far};
    }
  }
  return nearest;
}

double World::SurfaceDistance(const Eigen::Vector3d& p) const {
  if (!built_) throw std::logic_error("World::SurfaceDistance: call Build() after adding primitives");
  if (nodes_.empty()) return kInfinity;
  struct Entry {
    int node;                // node to visit
    double box_distance_sq;  // squared distance from p to its box: a lower bound
  };
  Entry stack[kStackSize];
  int top = 0;
  double best = kInfinity;
  stack[top++] = Entry{0, BoxDistanceSquared(nodes_[0].lo, nodes_[0].hi, p)};
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.box_distance_sq >= best * best) continue;  // nothing inside can be nearer
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (int k = node.right_or_first; k < node.right_or_first + node.count; ++k) {
        best = std::min(best, ordered_primitives_[k]->SurfaceDistance(p));
      }
      continue;
    }
    int near_child = entry.node + 1;
    int far_child = node.right_or_first;
    double d_near = BoxDistanceSquared(nodes_[near_child].lo, nodes_[near_child].hi, p);
    double d_far = BoxDistanceSquared(nodes_[far_child].lo, nodes_[far_child].hi, p);
    if (d_far < d_near) {
      std::swap(near_child, far_child);
      std::swap(d_near, d_far);
    }
    if (d_far < best * best) stack[top++] = Entry{far_child, d_far};
    if (d_near < best * best) stack[top++] = Entry{near_child, d_near};
  }
  return best;
}

Eigen::AlignedBox3d World::Bounds() const {
  Eigen::AlignedBox3d box;
  for (const auto& primitive : primitives_) box.extend(primitive->Bounds());
  return box;
}

}  // namespace unimap::sim
