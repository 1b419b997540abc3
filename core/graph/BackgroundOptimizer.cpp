#include "graph/BackgroundOptimizer.hpp"

#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

namespace unimap::graph {
namespace {

// Every node's pose, in node order.
std::vector<Eigen::Isometry3d> AllPoses(const PoseGraph& graph) {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(graph.NodeCount());
  for (std::size_t i = 0; i < graph.NodeCount(); ++i) poses.push_back(graph.Pose(static_cast<int>(i)));
  return poses;
}

// The default solve step: optimise the copy, report every node's pose.
OptimizedPoses OptimizeCopy(PoseGraph& graph, const PoseGraphOptions& options) {
  OptimizedPoses out;
  out.summary = graph.Optimize(options);
  out.T_world_node = AllPoses(graph);
  return out;
}

// A failed result carrying the submitted poses.
OptimizedPoses FailedResult(const PoseGraph& graph, const std::string& reason) {
  OptimizedPoses out;
  out.summary.ok = false;
  out.summary.reason = reason;
  out.summary.nodes = graph.NodeCount();
  out.summary.constraints = graph.ConstraintCount();
  out.T_world_node = AllPoses(graph);
  return out;
}

PoseGraphOptions Validated(PoseGraphOptions options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("BackgroundOptimizer: " + why);
  return options;
}

}  // namespace

BackgroundOptimizer::BackgroundOptimizer(PoseGraphOptions options)
    : BackgroundOptimizer(std::move(options), &OptimizeCopy) {}

BackgroundOptimizer::BackgroundOptimizer(PoseGraphOptions options, SolveFunction solve)
    : options_(Validated(std::move(options))), solve_(std::move(solve)) {
  if (!solve_) throw std::invalid_argument("BackgroundOptimizer: empty solve function");
  worker_ = std::thread([this] { Run(); });
}

BackgroundOptimizer::~BackgroundOptimizer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  job_ready_.notify_all();
  if (worker_.joinable()) worker_.join();
}

bool BackgroundOptimizer::Submit(const PoseGraph& graph) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (busy_) return false;
    job_ = graph;  // the copy; the worker holds this lock only briefly
    busy_ = true;
  }
  job_ready_.notify_one();
  return true;
}

std::optional<OptimizedPoses> BackgroundOptimizer::TakeResult() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<OptimizedPoses> out = std::move(result_);
  result_.reset();
  return out;
}

void BackgroundOptimizer::Wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return !busy_; });
}

bool BackgroundOptimizer::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return busy_;
}

void BackgroundOptimizer::Run() {
  for (;;) {
    std::optional<PoseGraph> graph;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      job_ready_.wait(lock, [this] { return stop_ || job_.has_value(); });
      // A job submitted before the destructor still runs (busy_ promised it).
      if (!job_.has_value()) return;
      graph = std::move(job_);
      job_.reset();
    }
    std::optional<OptimizedPoses> result;
    try {
      result = solve_(*graph, options_);
    } catch (const std::exception& e) {
      result = FailedResult(*graph, std::string("optimisation threw: ") + e.what());
    } catch (...) {
      result = FailedResult(*graph, "optimisation threw a non-standard exception");
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      result_ = std::move(result);
      busy_ = false;
    }
    idle_.notify_all();
  }
}

}  // namespace unimap::graph
