#pragma once
// Simulated data shared by the pipeline tests.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "Scenario.hpp"
#include "Simulator.hpp"

namespace unimap::pipeline::test {

// Per-process scratch folders: ctest runs the cases in parallel processes.
// Removed when the test process exits.
inline std::filesystem::path Scratch(const std::string& name) {
  struct Cleanup {
    std::vector<std::filesystem::path> dirs;
    ~Cleanup() {
      std::error_code ignored;
      for (const auto& d : dirs) std::filesystem::remove_all(d, ignored);
    }
  };
  static Cleanup cleanup;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("unimap_runner_test_" + std::to_string(::getpid()) + "_" + name);
  cleanup.dirs.push_back(dir);
  return dir;
}

inline const std::filesystem::path kPlatform =
    std::filesystem::path(UNIMAP_SOURCE_DIR) / "configs/platforms/rotating_hokuyo.yaml";

// The first duration_s of configs/scenarios/<scenario>.yaml with the
// rotating Hokuyo, simulated into Scratch(name).
inline std::filesystem::path Simulate(const std::string& name, const std::string& scenario, double duration_s) {
  const std::filesystem::path out = Scratch(name);
  std::filesystem::remove_all(out);
  sim::SimulationOptions options;
  options.out_dir = out;
  options.duration_s = duration_s;
  options.payload = kPlatform.string();
  sim::Simulator(
      sim::LoadScenario(std::filesystem::path(UNIMAP_SOURCE_DIR) / "configs/scenarios" / (scenario + ".yaml")), options)
      .Run();
  return out;
}

// 6 s of the tunnel scenario with the rotating Hokuyo, made once.
inline const std::filesystem::path& CleanDataset() {
  static const std::filesystem::path dir = Simulate("clean", "tunnel", 6.0);
  return dir;
}

}  // namespace unimap::pipeline::test
