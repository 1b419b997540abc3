#include "graph/LoopClosureSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace unimap::graph {

namespace {

// A set of translations [ix, ix + 2^level) x [iy, iy + 2^level) at one yaw
// and one z offset (cells), with the level-`level` score bounding them.
struct Node {
  int yaw = 0;    // yaw lattice index, 0 .. 2 K
  int iz = 0;     // z offset (cells)
  int ix = 0;     // first x offset (cells)
  int iy = 0;     // first y offset (cells)
  int level = 0;  // 0: one translation (a leaf)
  int score = 0;  // summed grid values (0..255 each)
};

// State of one Run: the scan discretised at every yaw, the kept maxima.
class SearchState {
 public:
  SearchState(const SubmapMatchGrid& grid, const LoopClosureOptions& options, int points, double radius_cells)
      : grid_(grid), options_(options), points_(points), radius_cells_(radius_cells) {
    min_score_ = static_cast<int>(std::ceil(options.min_search_score * 255.0 * points));
  }

  // Discretised scan at each yaw: cells of Rz(yaw) R_guess p + t_guess.
  std::vector<std::vector<int>> xs, ys, zs;
  std::vector<double> yaws;
  LoopClosureSearchStats stats;

  // Summed level values of the scan translated by the node's first offset.
  void Evaluate(Node* node) {
    ++stats.nodes;
    const std::uint8_t* level = grid_.Level(node->level);
    const Eigen::Vector3i& dims = grid_.dims();
    const std::size_t yaw = static_cast<std::size_t>(node->yaw);
    const int* x = xs[yaw].data();
    const int* y = ys[yaw].data();
    const int* z = zs[yaw].data();
    int sum = 0;
    for (int i = 0; i < points_; ++i) {
      const int cx = x[i] + node->ix;
      const int cy = y[i] + node->iy;
      const int cz = z[i] + node->iz;
      if (static_cast<unsigned>(cx) >= static_cast<unsigned>(dims.x()) ||
          static_cast<unsigned>(cy) >= static_cast<unsigned>(dims.y()) ||
          static_cast<unsigned>(cz) >= static_cast<unsigned>(dims.z())) {
        continue;
      }
      sum += level[(static_cast<std::size_t>(cx) * static_cast<std::size_t>(dims.y()) + static_cast<std::size_t>(cy)) *
                       static_cast<std::size_t>(dims.z()) +
                   static_cast<std::size_t>(cz)];
    }
    node->score = sum;
  }

  // True when the tile of `size` offsets starting at (ix, iy) reaches the disk.
  bool TouchesDisk(int ix, int iy, int size) const {
    const double nx = std::clamp(0, ix, ix + size - 1);
    const double ny = std::clamp(0, iy, iy + size - 1);
    return nx * nx + ny * ny <= radius_cells_ * radius_cells_ + 1e-9;
  }

  // True when no translation under a node with this bound can be kept.
  bool Prunable(int bound) const {
    if (bound < min_score_ || static_cast<double>(bound) < options_.candidate_score_ratio * best_) return true;
    return static_cast<int>(kept_.size()) >= options_.max_candidates && bound <= kept_.back().score;
  }

  // Branch and bound below a node (its score already evaluated).
  void Descend(const Node& node) {
    if (node.level == 0) {
      Offer(node);
      return;
    }
    const int half = 1 << (node.level - 1);
    Node children[4];
    int count = 0;
    for (int k = 0; k < 4; ++k) {
      Node child = node;
      child.level = node.level - 1;
      child.ix = node.ix + (k >> 1) * half;
      child.iy = node.iy + (k & 1) * half;
      if (!TouchesDisk(child.ix, child.iy, half)) continue;
      Evaluate(&child);
      children[count++] = child;
    }
    for (int k = 1; k < count; ++k) {  // insertion sort, best first
      for (int j = k; j > 0 && children[j].score > children[j - 1].score; --j) std::swap(children[j], children[j - 1]);
    }
    for (int k = 0; k < count; ++k) {
      if (Prunable(children[k].score)) break;
      Descend(children[k]);
    }
  }

  // The kept maxima (best first), those below the final ratio dropped.
  std::vector<Node> Kept() const {
    std::vector<Node> out;
    for (const Node& n : kept_) {
      if (static_cast<double>(n.score) >= options_.candidate_score_ratio * best_) out.push_back(n);
    }
    return out;
  }

 private:
  const SubmapMatchGrid& grid_;
  const LoopClosureOptions& options_;
  int points_;
  double radius_cells_;
  int min_score_ = 0;
  int best_ = 0;
  std::vector<Node> kept_;  // best first

  // Keeps a leaf unless a kept maximum near it scores at least as well;
  // drops the kept ones near it that score less.
  void Offer(const Node& leaf) {
    ++stats.leaves;
    if (leaf.score < min_score_) return;
    best_ = std::max(best_, leaf.score);
    const double r = grid_.resolution();
    const double yaw_step = yaws.size() > 1 ? yaws[1] - yaws[0] : 0.0;
    auto near = [&](const Node& a) {
      const double dx = (a.ix - leaf.ix) * r;
      const double dy = (a.iy - leaf.iy) * r;
      const double dz = (a.iz - leaf.iz) * r;
      return dx * dx + dy * dy + dz * dz <= options_.distinct_translation_m * options_.distinct_translation_m &&
             std::abs(a.yaw - leaf.yaw) * yaw_step <= options_.distinct_rotation_rad;
    };
    for (const Node& kept : kept_) {
      if (near(kept) && kept.score >= leaf.score) return;
    }
    kept_.erase(std::remove_if(kept_.begin(), kept_.end(), near), kept_.end());
    const auto at = std::find_if(kept_.begin(), kept_.end(), [&](const Node& n) { return n.score < leaf.score; });
    kept_.insert(at, leaf);
    if (static_cast<int>(kept_.size()) > options_.max_candidates) kept_.pop_back();
  }
};

}  // namespace

LoopClosureSearch::LoopClosureSearch(const SubmapMatchGrid& grid, const LoopClosureOptions& options)
    : grid_(grid), options_(options) {}

std::vector<LoopClosureCandidate> LoopClosureSearch::Run(const std::vector<Eigen::Vector3f>& points_body,
                                                         const Eigen::Isometry3d& T_submap_body_guess, double radius_m,
                                                         LoopClosureSearchStats* stats) const {
  std::vector<LoopClosureCandidate> candidates;
  if (points_body.empty()) return candidates;
  const int n = static_cast<int>(points_body.size());
  const double r = grid_.resolution();
  SearchState state(grid_, options_, n, radius_m / r);

  // Yaw lattice: a step moving the far points by about one cell.
  const Eigen::Matrix3d R_guess = T_submap_body_guess.linear();
  std::vector<Eigen::Vector3d> rotated(points_body.size());
  std::vector<double> ranges(points_body.size());
  for (std::size_t i = 0; i < points_body.size(); ++i) {
    rotated[i] = R_guess * points_body[i].cast<double>();
    ranges[i] = rotated[i].head<2>().norm();
  }
  const auto p90 = ranges.begin() + static_cast<std::ptrdiff_t>(ranges.size() * 9 / 10);
  std::nth_element(ranges.begin(), p90, ranges.end());
  double step = *p90 > 0.0 ? r / *p90 : options_.max_yaw_step_rad;
  step = std::clamp(step, options_.min_yaw_step_rad, options_.max_yaw_step_rad);
  const int half_steps = static_cast<int>(std::ceil(options_.yaw_window_rad / step - 1e-9));
  if (half_steps > 0) step = options_.yaw_window_rad / half_steps;
  for (int k = -half_steps; k <= half_steps; ++k) state.yaws.push_back(k * step);
  state.stats.yaw_steps = static_cast<int>(state.yaws.size());
  state.stats.yaw_step_rad = half_steps > 0 ? step : 0.0;

  const Eigen::Vector3d t_guess = T_submap_body_guess.translation();
  for (double yaw : state.yaws) {
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    std::vector<int> x(points_body.size()), y(points_body.size()), z(points_body.size());
    for (std::size_t i = 0; i < rotated.size(); ++i) {
      const Eigen::Vector3i cell = grid_.CellOf(Rz * rotated[i] + t_guess);
      x[i] = cell.x();
      y[i] = cell.y();
      z[i] = cell.z();
    }
    state.xs.push_back(std::move(x));
    state.ys.push_back(std::move(y));
    state.zs.push_back(std::move(z));
  }

  // Roots: tiles of the top level over the window, best first.
  const int window = static_cast<int>(std::ceil(radius_m / r - 1e-9));
  const int z_window = static_cast<int>(std::floor(options_.z_window_m / r + 1e-9));
  const int top = grid_.levels() - 1;
  const int tile = 1 << top;
  std::vector<Node> roots;
  for (int yaw = 0; yaw < static_cast<int>(state.yaws.size()); ++yaw) {
    for (int iz = -z_window; iz <= z_window; ++iz) {
      for (int ix = -window; ix <= window; ix += tile) {
        for (int iy = -window; iy <= window; iy += tile) {
          if (!state.TouchesDisk(ix, iy, tile)) continue;
          Node root;
          root.yaw = yaw;
          root.iz = iz;
          root.ix = ix;
          root.iy = iy;
          root.level = top;
          state.Evaluate(&root);
          roots.push_back(root);
        }
      }
    }
  }
  std::sort(roots.begin(), roots.end(), [](const Node& a, const Node& b) { return a.score > b.score; });
  for (const Node& root : roots) {
    if (state.Prunable(root.score)) break;
    state.Descend(root);
  }

  for (const Node& leaf : state.Kept()) {
    LoopClosureCandidate c;
    c.T_submap_body.linear() =
        Eigen::AngleAxisd(state.yaws[static_cast<std::size_t>(leaf.yaw)], Eigen::Vector3d::UnitZ()).toRotationMatrix() *
        R_guess;
    c.T_submap_body.translation() = t_guess + r * Eigen::Vector3d(leaf.ix, leaf.iy, leaf.iz);
    c.score = leaf.score / (255.0 * n);
    candidates.push_back(c);
  }
  if (stats != nullptr) *stats = state.stats;
  return candidates;
}

}  // namespace unimap::graph
