// `unimap demo`: the first thing a new user runs. Simulates the paper's
// tunnel with the rotating Hokuyo, maps it, evaluates it against the ground
// truth and prints the result beside the paper's numbers.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "MappingRun.hpp"
#include "NumberChecks.hpp"
#include "OutputFolder.hpp"
#include "Scenario.hpp"
#include "SignalGuard.hpp"
#include "Simulator.hpp"
#include "TextFormat.hpp"
#include "TextTable.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

namespace fs = std::filesystem;

struct DemoOptions {
  std::string out_dir = "unimap-demo";  // everything goes here (dataset in data/)
  std::string configs;                  // folder with scenarios/ and platforms/ (default: found)
  double duration_s = 0.0;              // simulate only this much (0: the whole 15-minute flight)
  int threads = 2;                      // GPF threads (the README machine has two cores)
};

// configs/ in the working folder, else the installed share/unimap/configs
// beside the executable.
fs::path FindConfigs(const std::string& given) {
  if (!given.empty()) return given;
  std::vector<fs::path> candidates = {"configs"};
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path().parent_path() / "share" / "unimap" / "configs");
    candidates.push_back(exe.parent_path().parent_path().parent_path() / "configs");  // build/bin -> source tree
  }
  for (const fs::path& c : candidates) {
    if (fs::is_regular_file(c / "scenarios" / "tunnel.yaml")) return c;
  }
  throw InputError(
      "unimap demo: cannot find configs/scenarios/tunnel.yaml (run from the source folder or pass "
      "--configs)");
}

// The evaluation beside the paper's Table (simulated tunnel, rotating Hokuyo).
void PrintComparison(const eval::TrajectoryMetrics& m) {
  const auto opt = [](const std::optional<double>& v, int digits) { return v ? Fixed(*v, digits) : "n/a"; };
  TextTable table({"metric", "unimap", "paper"});
  table.AddRow({"max position error x / y / z (m)",
                Fixed(m.max_abs_error_m.x(), 2) + " / " + Fixed(m.max_abs_error_m.y(), 2) + " / " +
                    Fixed(m.max_abs_error_m.z(), 2),
                "2.00 / 0.37 / 1.11"});
  table.AddRow({"translational drift (% of path)", opt(m.drift_percent, 2), "1.34"});
  table.AddRow({"mean abs roll / pitch / yaw error (deg)",
                Fixed(m.mean_abs_rot_error_deg.x(), 2) + " / " + Fixed(m.mean_abs_rot_error_deg.y(), 2) + " / " +
                    Fixed(m.mean_abs_rot_error_deg.z(), 2),
                "0.14 / 0.15 / 0.24"});
  table.AddRow({"rotational drift (deg/m)", opt(m.rot_drift_deg_per_m, 4), "0.003"});
  table.AddRow({"ATE RMSE, SE(3)-aligned (m)", Fixed(m.ate_rmse_m, 3), "-"});
  table.AddRow({"path length (m)", Fixed(m.path_length_m, 1), "165"});
  std::cout << '\n';
  table.Print(std::cout, "  ");
}

int RunDemo(const DemoOptions& options) {
  try {
    const fs::path configs = FindConfigs(options.configs);
    const fs::path out(options.out_dir);
    const fs::path data = out / "data";
    const sim::Scenario scenario = sim::LoadScenario(configs / "scenarios" / "tunnel.yaml");
    sim::SimulationOptions simulation;
    simulation.out_dir = data;
    if (options.duration_s > 0.0) simulation.duration_s = options.duration_s;
    simulation.stop = &SignalGuard::StopFlag();
    PrepareOutputFolder(out, "--out");
    std::cout << "1/3 simulating the paper's tunnel (rotating Hokuyo) into " << data.string() << " ...\n";
    const sim::SimulationSummary s = sim::Simulator(scenario, simulation).Run();
    std::cout << "    " << Fixed(s.duration_s, 0) << " s of data, " << Fixed(s.path_length_m, 1) << " m, " << s.scans
              << " scans, in " << Fixed(s.wall_s, 1) << " s\n";

    if (s.interrupted) {
      std::cout << "interrupted: the dataset holds the first " << Fixed(s.duration_s, 1) << " s\n";
      return 0;  // the exit code is the signal's (SignalGuard::ExitCode)
    }
    std::cout << "2/3 mapping it (unimap run) ...\n";
    MappingRunOptions run;
    run.platform_file = s.payload_source;
    run.data_dir = data.string();
    run.out_dir = out.string();
    run.threads = options.threads;
    run.quiet = !isatty(STDERR_FILENO);
    const int code = RunMappingToFolder(run);
    if (code != 0 || SignalGuard::Received() != 0) return code;  // stopped: no evaluation of a cut run

    std::cout << "3/3 evaluation against the ground truth:\n";
    const eval::TrajectoryEvaluation evaluation = eval::EvaluateTrajectory(
        io::ReadTumTrajectory(out / "trajectory.tum"), io::ReadTumTrajectory(data / "groundtruth.tum"), {});
    PrintComparison(evaluation.metrics);
    std::cout << "\nreport: " << (out / "report.html").string() << "\nmaps:   " << (out / "map.pcd").string() << ", "
              << (out / "map.ply").string() << ", " << (out / "map.bt").string() << '\n';
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddDemoCommand(CLI::App* app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* cmd = app->add_subcommand(
      "demo", "Simulate the paper's tunnel, map it with the rotating Hokuyo and compare with the paper");
  cmd->add_option("--out", options->out_dir, "Output folder (default unimap-demo)");
  cmd->add_option("--configs", options->configs, "Folder holding scenarios/ and platforms/ (default: found)");
  cmd->add_option("--duration-s", options->duration_s, "Simulate only this much of the flight (s)")
      ->check(FinitePositive());
  cmd->add_option("--threads", options->threads, "Threads for particle weighting")->check(CLI::Range(1, 64));
  cmd->callback([options]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: stop, write what was processed, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunDemo(*options));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
