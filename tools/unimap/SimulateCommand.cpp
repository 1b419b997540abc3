// `unimap simulate`: a simulated dataset for a scenario and payload.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "Commands.hpp"
#include "NumberChecks.hpp"
#include "OutputFolder.hpp"
#include "Scenario.hpp"
#include "ScenarioVariant.hpp"
#include "SignalGuard.hpp"
#include "Simulator.hpp"
#include "TextFormat.hpp"
#include "WorldMap.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

struct SimulateOptions {
  std::string scenario;                // scenario YAML
  std::string out;                     // dataset folder
  std::optional<std::uint64_t> seed;   // replaces the scenario's
  std::optional<std::string> payload;  // platform file or plugin name
  std::optional<double> duration_s;    // stop early
  bool quiet = false;                  // no progress line
  sim::ScenarioVariant variant;        // speed and IMU error scales
};

void PrintSummary(const sim::SimulationSummary& s, const std::string& scenario_file, const std::string& out) {
  const double rtf = s.wall_s > 0.0 ? s.duration_s / s.wall_s : 0.0;
  const double return_pct = s.rays > 0 ? 100.0 * static_cast<double>(s.returns) / static_cast<double>(s.rays) : 0.0;
  std::cout << "scenario   " << s.scenario << "  (" << scenario_file << "), seed " << s.seed << '\n'
            << "payload    " << s.payload << "  (" << s.payload_source << ")\n"
            << "world      " << s.world << '\n'
            << "duration   " << Fixed(s.duration_s, 1) << " s\n"
            << "path       " << Fixed(s.path_length_m, 1) << " m, max speed " << Fixed(s.max_speed_m_s, 3) << " m/s\n"
            << "imu        " << s.imu_samples << " samples (and as many ground-truth poses)\n"
            << "encoder    " << s.encoder_samples << " samples\n"
            << "scans      " << s.scans << " written";
  if (s.empty_scans > 0) std::cout << ", " << s.empty_scans << " empty sweeps skipped";
  std::cout << '\n'
            << "rays       " << s.rays << " cast, " << s.returns << " returns (" << Fixed(return_pct, 1) << " %)\n"
            << "output     " << out << "  (" << Fixed(static_cast<double>(s.bytes) / 1e6, 1) << " MB)\n"
            << "time       " << Fixed(s.wall_s, 2) << " s wall, " << Fixed(s.cpu_s, 2) << " s CPU, real-time factor "
            << Fixed(rtf, 1) << ", " << Fixed(s.wall_s > 0 ? static_cast<double>(s.rays) / s.wall_s / 1e6 : 0.0, 2)
            << " M rays/s\n";
}

int RunSimulate(const SimulateOptions& options) {
  const bool show_progress = !options.quiet && isatty(STDERR_FILENO);
  try {
    const sim::Scenario scenario = sim::ApplyVariant(sim::LoadScenario(options.scenario), options.variant);
    sim::SimulationOptions run;
    run.out_dir = options.out;
    run.seed = options.seed;
    run.payload = options.payload;
    run.duration_s = options.duration_s;
    run.stop = &SignalGuard::StopFlag();
    PrepareOutputFolder(options.out, "--out");
    if (show_progress) {
      run.progress = [](double fraction) {
        std::fprintf(stderr, "\rsimulating %3d %%", static_cast<int>(100.0 * fraction));
        if (fraction >= 1.0) std::fprintf(stderr, "\n");
      };
    }
    const sim::SimulationSummary summary = sim::Simulator(scenario, run).Run();
    // The true map: the world's surfaces as seen from the true trajectory (docs/simulation.md).
    const sim::WorldMapSummary world_map =
        sim::WriteWorldMap(scenario, sim::Simulator::LoadPayload(summary.payload_source), summary.duration_s,
                           std::filesystem::path(options.out) / sim::kWorldMapFile);
    PrintSummary(summary, options.scenario, options.out);
    if (summary.interrupted) {
      std::cout << "interrupted: the dataset holds the first " << Fixed(summary.duration_s, 1)
                << " s, complete (signal " << SignalGuard::Received() << ")\n";
    }
    std::cout << "true map   " << world_map.points << " points from " << world_map.viewpoints << " viewpoints, rays to "
              << Fixed(world_map.max_range_m, 0) << " m, " << Fixed(world_map.wall_s, 2)
              << " s: " << world_map.file.string() << '\n';
    return 0;
  } catch (const Error& e) {
    std::cerr << (show_progress ? "\n" : "") << "error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {  // e.g. a file system failure while writing
    std::cerr << (show_progress ? "\n" : "") << "error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace

void AddSimulateCommand(CLI::App* app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app->add_subcommand(
      "simulate", "Write a simulated dataset (IMU, encoder, LiDAR, ground truth, world) for a scenario");
  cmd->add_option("--scenario", options->scenario, "Scenario YAML (configs/scenarios/*.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", options->out, "Dataset folder to write (created if needed)")->required();
  cmd->add_option("--seed", options->seed, "Random seed (default: the scenario's)");
  cmd->add_option("--payload", options->payload,
                  "Platform YAML or plugin name (its defaults) instead of the scenario's payload");
  cmd->add_option("--duration-s", options->duration_s, "Simulate only the first T seconds")->check(FinitePositive());
  cmd->add_option("--speed-scale", options->variant.speed_scale,
                  "The same path S times as fast (speed and yaw rate x S, acceleration x S^2, dwells / S)");
  cmd->add_option("--imu-noise-scale", options->variant.imu_noise_scale, "IMU white noise x K");
  cmd->add_option("--imu-bias-scale", options->variant.imu_bias_scale, "IMU start biases and bias walks x B");
  cmd->add_flag("--quiet", options->quiet, "No progress line");
  cmd->callback([options]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: end the data there, finish the dataset, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunSimulate(*options));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
