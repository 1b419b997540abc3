#include "graph/BackgroundOptimizer.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "PoseGraphFixtures.hpp"

namespace unimap::graph {
namespace {

using test::CircleTruth;
using test::NoisyLoopGraph;

// A gate the test opens by hand: lets a solve step block deterministically
// (no timing assumptions) while the test checks the busy behaviour.
class Gate {
 public:
  void Open() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      open_ = true;
    }
    cv_.notify_all();
  }
  void Pass() {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait(lock, [this] { return open_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool open_ = false;
};

// A solve step that waits for the gate, then reports the node count in
// summary.iterations (so the test can tell the jobs apart).
BackgroundOptimizer::SolveFunction GatedSolve(Gate* gate, std::atomic<int>* finished) {
  return [gate, finished](PoseGraph& graph, const PoseGraphOptions&) {
    gate->Pass();
    OptimizedPoses out;
    out.summary.ok = true;
    out.summary.iterations = static_cast<int>(graph.NodeCount());
    for (int i = 0; i < static_cast<int>(graph.NodeCount()); ++i) out.T_world_node.push_back(graph.Pose(i));
    finished->fetch_add(1);
    return out;
  };
}

PoseGraph GraphWithNodes(int n) {
  PoseGraph graph;
  for (int i = 0; i < n; ++i) graph.AddNode(Eigen::Isometry3d::Identity());
  return graph;
}

TEST(BackgroundOptimizer, ResultEqualsTheSynchronousOptimization) {
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(36);
  const PoseGraph graph = NoisyLoopGraph(truth, /*odometry_noise=*/true, /*seed=*/42);
  PoseGraph synchronous = graph;
  const OptimizationSummary expected = synchronous.Optimize(PoseGraphOptions{});
  ASSERT_TRUE(expected.ok);

  BackgroundOptimizer optimizer(PoseGraphOptions{});
  EXPECT_FALSE(optimizer.TakeResult().has_value());
  ASSERT_TRUE(optimizer.Submit(graph));
  optimizer.Wait();
  EXPECT_FALSE(optimizer.busy());
  const std::optional<OptimizedPoses> result = optimizer.TakeResult();
  ASSERT_TRUE(result.has_value());
  EXPECT_FALSE(optimizer.TakeResult().has_value());  // handed out once
  ASSERT_TRUE(result->summary.ok) << result->summary.reason;
  EXPECT_EQ(result->summary.iterations, expected.iterations);
  EXPECT_EQ(result->summary.final_cost, expected.final_cost);
  ASSERT_EQ(result->T_world_node.size(), truth.size());
  // Same input, same single-threaded solve: the same poses bit for bit.
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_TRUE(result->T_world_node[i].matrix() == synchronous.Pose(static_cast<int>(i)).matrix()) << i;
  }
  // The submitted graph is a copy: the caller's graph is untouched.
  EXPECT_GT((graph.Pose(20).translation() - synchronous.Pose(20).translation()).norm(), 0.01);
}

TEST(BackgroundOptimizer, RefusesWorkWhileBusyAndKeepsTheLatestResult) {
  Gate first_gate;
  std::atomic<int> finished{0};
  BackgroundOptimizer optimizer(PoseGraphOptions{}, GatedSolve(&first_gate, &finished));
  ASSERT_TRUE(optimizer.Submit(GraphWithNodes(3)));
  EXPECT_TRUE(optimizer.busy());
  EXPECT_FALSE(optimizer.Submit(GraphWithNodes(5)));  // refused, not queued
  EXPECT_FALSE(optimizer.TakeResult().has_value());
  first_gate.Open();
  optimizer.Wait();
  EXPECT_FALSE(optimizer.busy());
  EXPECT_EQ(finished.load(), 1);

  // Two more jobs without taking: only the newest result is kept.
  ASSERT_TRUE(optimizer.Submit(GraphWithNodes(7)));
  optimizer.Wait();
  ASSERT_TRUE(optimizer.Submit(GraphWithNodes(9)));
  optimizer.Wait();
  const std::optional<OptimizedPoses> result = optimizer.TakeResult();
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->summary.iterations, 9);
  EXPECT_EQ(result->T_world_node.size(), 9u);
  EXPECT_FALSE(optimizer.TakeResult().has_value());
  EXPECT_EQ(finished.load(), 3);
}

TEST(BackgroundOptimizer, ASolveThatThrowsBecomesAFailedResult) {
  BackgroundOptimizer optimizer(PoseGraphOptions{}, [](PoseGraph&, const PoseGraphOptions&) -> OptimizedPoses {
    throw std::runtime_error("boom");
  });
  ASSERT_TRUE(optimizer.Submit(GraphWithNodes(4)));
  optimizer.Wait();
  const std::optional<OptimizedPoses> result = optimizer.TakeResult();
  ASSERT_TRUE(result.has_value());
  EXPECT_FALSE(result->summary.ok);
  EXPECT_NE(result->summary.reason.find("boom"), std::string::npos);
  EXPECT_EQ(result->T_world_node.size(), 4u);
  EXPECT_TRUE(optimizer.Submit(GraphWithNodes(2)));  // still usable
  optimizer.Wait();
}

TEST(BackgroundOptimizer, DestructorLetsTheRunningJobFinish) {
  Gate gate;
  std::atomic<int> finished{0};
  std::thread opener;
  {
    BackgroundOptimizer optimizer(PoseGraphOptions{}, GatedSolve(&gate, &finished));
    ASSERT_TRUE(optimizer.Submit(GraphWithNodes(3)));
    // The gate opens from another thread while the destructor is joining
    // (or before; either way the destructor must wait for the job).
    opener = std::thread([&gate] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      gate.Open();
    });
  }
  EXPECT_EQ(finished.load(), 1);
  opener.join();

  // The real solver, destroyed right after a submit: no hang, no crash.
  const std::vector<Eigen::Isometry3d> truth = CircleTruth(36);
  {
    BackgroundOptimizer optimizer(PoseGraphOptions{});
    EXPECT_TRUE(optimizer.Submit(NoisyLoopGraph(truth, /*odometry_noise=*/true, /*seed=*/5)));
  }
}

TEST(BackgroundOptimizer, RejectsInvalidOptions) {
  PoseGraphOptions bad;
  bad.threads = 0;
  EXPECT_THROW(BackgroundOptimizer{bad}, std::invalid_argument);
  EXPECT_THROW(BackgroundOptimizer(PoseGraphOptions{}, BackgroundOptimizer::SolveFunction{}), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::graph
