// The pose-graph solve (graph::PoseGraph::Optimize) on graphs shaped like
// the Mapper's after N key scans: a submap node every 10 key scans, each
// key scan tied to the two submaps it was inserted into (and so, as in
// pipeline::TrajectoryGraph, not by odometry to the one before, with which
// it shares a submap), a loop closure every 15 key scans after the first 200.
// Besides the time, the counter solve_peak_MiB is the resident memory the
// solve adds at its peak (free heap pages returned and the process's
// high-water mark reset before it, /proc/self/clear_refs), measured on the
// first iteration: the memory over long runs in docs/reliability.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "graph/PoseGraph.hpp"
#include "graph/PoseGraphOptions.hpp"

namespace unimap::bench {
namespace {

// A /proc/self/status field in KiB (0 when absent).
long StatusKib(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + key.size());
  }
  return 0;
}

// Returns the heap's free pages to the system (so that the solve's
// allocations fault in pages rather than reuse freed ones) and resets
// VmHWM to the current VmRSS (Linux 4.0 and later); false when refused.
bool ResetPeak() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  return static_cast<bool>(clear.flush());
}

Eigen::Isometry3d PathPose(double s_m) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(s_m, 0.1 * std::sin(s_m), 0.0);
  T.linear() = Eigen::AngleAxisd(0.01 * s_m, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

graph::PoseGraph MapperShapedGraph(int key_scans) {
  std::mt19937 rng(1);
  std::normal_distribution<double> noise_m(0.0, 0.01);
  graph::PoseGraph g;
  const graph::Matrix6d sqrt_information = graph::Matrix6d::Identity() * 10.0;
  std::vector<int> submaps;
  const auto link = [&](int from, int to, graph::ConstraintKind kind) {
    graph::PoseConstraint c;
    c.from_node = from;
    c.to_node = to;
    c.T_from_to = g.Pose(from).inverse() * g.Pose(to);
    c.T_from_to.translation() += Eigen::Vector3d(noise_m(rng), noise_m(rng), noise_m(rng));
    c.sqrt_information = sqrt_information;
    c.kind = kind;
    g.AddConstraint(c);
  };
  for (int k = 0; k < key_scans; ++k) {
    const double s_m = 0.05 * k;
    if (k % 10 == 0) submaps.push_back(g.AddNode(PathPose(s_m)));
    Eigen::Isometry3d T = PathPose(s_m);
    T.translation() += Eigen::Vector3d(noise_m(rng), noise_m(rng), noise_m(rng));
    const int key = g.AddNode(T);
    link(submaps.back(), key, graph::ConstraintKind::kScanInSubmap);
    if (submaps.size() >= 2) link(submaps[submaps.size() - 2], key, graph::ConstraintKind::kScanInSubmap);
    if (k > 200 && k % 15 == 0) {
      const std::size_t older = static_cast<std::size_t>(k) * 7919u % (submaps.size() - 5);
      link(submaps[older], key, graph::ConstraintKind::kLoopClosure);
    }
  }
  return g;
}

void BM_PoseGraphOptimize(benchmark::State& state) {
  const graph::PoseGraph graph = MapperShapedGraph(static_cast<int>(state.range(0)));
  const graph::PoseGraphOptions options;
  double peak_mib = -1.0;
  for (auto _ : state) {
    state.PauseTiming();
    graph::PoseGraph work = graph;
    const bool measure = peak_mib < 0.0 && ResetPeak();
    const long rss_kib = StatusKib("VmRSS:");
    state.ResumeTiming();
    const graph::OptimizationSummary summary = work.Optimize(options);
    state.PauseTiming();
    if (!summary.ok) state.SkipWithError(summary.reason.c_str());
    if (measure) peak_mib = static_cast<double>(StatusKib("VmHWM:") - rss_kib) / 1024.0;
    state.ResumeTiming();
  }
  state.counters["nodes"] = static_cast<double>(graph.NodeCount());
  state.counters["constraints"] = static_cast<double>(graph.ConstraintCount());
  state.counters["solve_peak_MiB"] = peak_mib;
}

}  // namespace
}  // namespace unimap::bench

BENCHMARK(unimap::bench::BM_PoseGraphOptimize)->Arg(900)->Arg(1800)->Arg(3600)->Unit(benchmark::kMillisecond);
