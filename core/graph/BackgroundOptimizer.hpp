#pragma once
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include "graph/PoseGraph.hpp"
#include "graph/PoseGraphOptions.hpp"

namespace unimap::graph {

// The result of one background optimisation.
struct OptimizedPoses {
  std::vector<Eigen::Isometry3d> T_world_node;  // per node id; unoptimised (as submitted) when !summary.ok
  OptimizationSummary summary;                  // outcome of PoseGraph::Optimize
};

// Optimises copies of a pose graph on one background thread, so the caller
// (the mapper) never waits for Ceres. At most one optimisation runs at a
// time; a Submit while one runs is refused, not queued.
class BackgroundOptimizer {
 public:
  // The solve step: optimises the graph copy in place and returns the poses.
  using SolveFunction = std::function<OptimizedPoses(PoseGraph& graph, const PoseGraphOptions& options)>;

  // Starts the worker thread; solves with PoseGraph::Optimize. Throws
  // std::invalid_argument when !options.IsValid.
  explicit BackgroundOptimizer(PoseGraphOptions options);
  // The same with another solve step (instrumentation, tests). Throws
  // std::invalid_argument when !options.IsValid or solve is empty.
  BackgroundOptimizer(PoseGraphOptions options, SolveFunction solve);
  // Joins the worker; an optimisation already submitted runs to the end.
  ~BackgroundOptimizer();
  BackgroundOptimizer(const BackgroundOptimizer&) = delete;
  BackgroundOptimizer& operator=(const BackgroundOptimizer&) = delete;

  // Starts optimising a copy of graph unless one optimisation is running;
  // returns false (and ignores graph) when busy. Never waits for a solve.
  bool Submit(const PoseGraph& graph);
  // The latest finished result, handed out once (nullopt when none new);
  // never waits. An exception thrown by the solve step becomes a result
  // with summary.ok == false. Results not taken are replaced by newer ones.
  std::optional<OptimizedPoses> TakeResult();
  // Blocks until no optimisation is running.
  void Wait();
  // True from a successful Submit until its result is ready.
  bool busy() const;

 private:
  void Run();

  const PoseGraphOptions options_;
  const SolveFunction solve_;
  mutable std::mutex mutex_;
  std::condition_variable job_ready_;     // worker: a job or stop
  std::condition_variable idle_;          // Wait(): busy_ became false
  std::optional<PoseGraph> job_;          // submitted, not yet picked up
  std::optional<OptimizedPoses> result_;  // finished, not yet taken
  bool busy_ = false;                     // a job is pending or running
  bool stop_ = false;                     // the destructor asked the worker to end
  std::thread worker_;                    // started last, in the constructor body
};

}  // namespace unimap::graph
