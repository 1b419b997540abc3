#pragma once
// The stage benchmarks' cases, shared by every benchmark file.
#include <benchmark/benchmark.h>

#include <iterator>

#include "StageInputs.hpp"

namespace unimap::bench {

struct Case {
  const char* scenario;
  const char* platform;
  double duration_s;
};

// One pair per payload, at the scenario it was made for, and the
// robustness matrix's slowest pair (10 s each).
inline constexpr Case kCases[] = {
    {"corridor_loop", "fixed_vlp16", 10.0},
    {"patio", "rotating_vlp16", 10.0},
    {"narrow_hallway", "rotating_hokuyo", 10.0},
    {"patio", "fixed_vlp16", 10.0},
};

// The inputs of the case state.range(0) names.
inline const StageInputs& CaseInputs(const benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  return Inputs(c.scenario, c.platform, c.duration_s);
}

// Registers every case.
inline void AllCases(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i) b->Arg(i);
}

}  // namespace unimap::bench
