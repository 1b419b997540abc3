// `unimap bench`: speed figures, written to docs/benchmarks.md. Each
// benchmark is a BenchmarkCase in Cases(); add a case to add a section.
#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "Commands.hpp"
#include "MapEvaluation.hpp"
#include "MapOutputs.hpp"
#include "RobustnessMatrix.hpp"
#include "Scenario.hpp"
#include "Simulator.hpp"
#include "TextFormat.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/DatasetReader.hpp"
#include "io/PlyWriter.hpp"
#include "io/TumTrajectory.hpp"
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Mapper.hpp"
#include "pipeline/MapperSettings.hpp"
#include "pipeline/StageTimes.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

struct BenchOptions {
  std::string out = "docs/benchmarks.md";        // report to (re)write
  std::string configs = "configs";               // folder with scenarios/ and platforms/
  bool quick = false;                            // shortened runs, for a smoke test
  std::string kitti = "../shared/data/kitti00";  // KITTI-style folder for the real-data case (absent: skipped)
  std::string kiss_icp =
      "build-peers/runner/build/kiss_icp_runner";  // peer (scripts/peer_kiss_icp.sh); absent: skipped
};

// One measured figure of a benchmark.
struct BenchmarkFigure {
  std::string name;   // "wall time"
  std::string value;  // "11.5 s"
};

// One benchmark: what it measures and how to run it.
struct BenchmarkCase {
  std::string name;                                                      // section title, stable across runs
  std::string description;                                               // one paragraph: what runs, on what data
  std::function<std::vector<BenchmarkFigure>(const BenchOptions&)> run;  // throws on failure
};

// Simulates a scenario with its default payload into a temporary folder.
std::vector<BenchmarkFigure> SimulateScenario(const BenchOptions& options, const std::string& scenario_name) {
  const std::filesystem::path file = std::filesystem::path(options.configs) / "scenarios" / (scenario_name + ".yaml");
  const sim::Scenario scenario = sim::LoadScenario(file);
  sim::SimulationOptions run;
  run.out_dir = std::filesystem::temp_directory_path() / ("unimap-bench-" + std::to_string(getpid()));
  if (options.quick) run.duration_s = 60.0;
  sim::SimulationSummary s;
  try {
    s = sim::Simulator(scenario, run).Run();
  } catch (...) {
    std::filesystem::remove_all(run.out_dir);
    throw;
  }
  std::filesystem::remove_all(run.out_dir);
  const double rays = static_cast<double>(s.rays);
  return {{"payload", s.payload + " (" + s.payload_source + ")"},
          {"data duration", Fixed(s.duration_s, 1) + " s"},
          {"path length", Fixed(s.path_length_m, 1) + " m, max speed " + Fixed(s.max_speed_m_s, 3) + " m/s"},
          {"scans / rays", std::to_string(s.scans) + " / " + std::to_string(s.rays)},
          {"dataset size", Fixed(static_cast<double>(s.bytes) / 1e6, 1) + " MB"},
          {"wall time", Fixed(s.wall_s, 2) + " s"},
          {"CPU time", Fixed(s.cpu_s, 2) + " s"},
          {"real-time factor (data duration / wall time)", Fixed(s.duration_s / s.wall_s, 1)},
          {"rays per second", Fixed(rays / s.wall_s / 1e6, 2) + " M"}};
}

// One figure per stage of pipeline::StageTimes: seconds and share of the
// processing time (the map stages run on the map thread, on the same core).
std::vector<BenchmarkFigure> StageFigures(const pipeline::StageTimes& t, double processing_s) {
  const std::pair<const char*, double> stages[] = {{"deskew", t.deskew_s},
                                                   {"downsampling", t.downsample_s},
                                                   {"particle filter + refinement", t.match_s},
                                                   {"ESKF", t.eskf_s},
                                                   {"map insertion (surfaces, occupancy, rays)", t.map_surface_s},
                                                   {"distance-field update", t.map_distance_s},
                                                   {"field export", t.map_export_s},
                                                   {"loop-closure search", t.loop_search_s},
                                                   {"pose-graph optimisation", t.optimization_s}};
  std::vector<BenchmarkFigure> figures;
  for (const auto& [name, seconds] : stages) {
    figures.push_back(
        {std::string("stage: ") + name,
         Fixed(seconds, 2) + " s (" + Fixed(processing_s > 0.0 ? 100.0 * seconds / processing_s : 0.0, 1) + " %)"});
  }
  return figures;
}

// Simulates a scenario with its default payload or the shipped platform
// `payload` (not timed), then localises it with the full mapper (timed, on
// the one pinned core, background threads included).
std::vector<BenchmarkFigure> LocalizeScenario(const BenchOptions& options, const std::string& scenario_name,
                                              const std::string& payload = "") {
  namespace fs = std::filesystem;
  const fs::path file = fs::path(options.configs) / "scenarios" / (scenario_name + ".yaml");
  sim::SimulationOptions run;
  run.out_dir = fs::temp_directory_path() / ("unimap-bench-run-" + std::to_string(getpid()));
  if (options.quick) run.duration_s = 60.0;
  if (!payload.empty()) run.payload = (fs::path(options.configs) / "platforms" / (payload + ".yaml")).string();
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{run.out_dir};
  const sim::SimulationSummary s = sim::Simulator(sim::LoadScenario(file), run).Run();
  const Platform platform = sim::Simulator::LoadPayload(s.payload_source);
  pipeline::ResetPeakRss();    // the peak of this run, not of the cases before it
  pipeline::SceneScale scene;  // as `unimap run` sizes the map's voxel
  {
    io::DatasetReader probe(run.out_dir);
    scene = pipeline::ReadSceneScale(probe, pipeline::MapperOptionsFor(platform).localizer.scans_per_3d_scan);
  }
  pipeline::Mapper mapper(pipeline::MapperOptionsFor(platform, scene), platform.plugin.plugin);
  io::DatasetReader reader(run.out_dir);
  const fs::path odometry_file = run.out_dir / "odometry.tum";
  pipeline::RunSummary summary;
  {
    io::TumTrajectoryWriter trajectory(odometry_file);
    summary = pipeline::RunDataset(reader, mapper, trajectory, pipeline::RunOptions{});
  }
  if (!summary.error.empty()) throw Error(summary.error);
  // Accuracy (not timed): the trajectory, the map as `unimap run` writes it
  // (map.ply) against the world's true surfaces after the ATE alignment, and
  // the errors at the first loop closure.
  const std::vector<StampedPose> truth = io::ReadTumTrajectory(run.out_dir / "groundtruth.tum");
  const std::vector<StampedPose> optimized = mapper.OptimizedTrajectory();
  const eval::TrajectoryEvaluation evaluation = eval::EvaluateTrajectory(optimized, truth, {});
  const fs::path map_file = run.out_dir / "map.ply";
  io::WritePly(map_file, mapper.MapPoints(MapOutputOptions{}.map_voxel_m));
  const eval::MapErrorStats map_error =
      *EvaluateMapFile(map_file, run.out_dir / "world.yaml", evaluation.errors.alignment.T_target_source).aligned;
  const pipeline::MapperStats mapping = mapper.stats();
  std::optional<LoopPointErrors> loop_point;
  if (mapping.first_loop_closure_time_s >= 0.0) {
    loop_point = ComputeLoopPointErrors(io::ReadTumTrajectory(odometry_file), optimized, truth,
                                        mapping.first_loop_closure_time_s);
  }
  const pipeline::LocalizerStats& stats = mapper.localizer_stats();
  const auto& m = evaluation.metrics;
  const auto opt = [](const std::optional<double>& v, int digits) { return v ? Fixed(*v, digits) : "n/a"; };
  std::vector<BenchmarkFigure> figures = {
      {"payload", s.payload + " (" + s.payload_source + ")"},
      {"data duration", Fixed(summary.data_duration_s, 1) + " s, " + std::to_string(stats.scans) + " scans (" +
                            std::to_string(stats.scans_matched) + " matched)"},
      {"3D scans / submaps / loop closures", std::to_string(mapping.key_scans) + " / " +
                                                 std::to_string(mapping.submaps) + " / " +
                                                 std::to_string(mapping.loop_closures)},
      {"processing time", Fixed(summary.processing_s, 2) + " s"},
      {"real-time factor (data duration / processing time)", Fixed(summary.realtime_factor, 2)},
      {"peak RSS (process, during the run)", Fixed(summary.peak_rss_mb, 0) + " MiB"},
      {"ate_rmse_m / drift_percent", Fixed(m.ate_rmse_m, 3) + " / " + opt(m.drift_percent, 2)},
      {"max_abs_error_m (x, y, z)", Fixed(m.max_abs_error_m.x(), 2) + ", " + Fixed(m.max_abs_error_m.y(), 2) + ", " +
                                        Fixed(m.max_abs_error_m.z(), 2)},
      {"mean_abs_rot_error_deg (roll, pitch, yaw)", Fixed(m.mean_abs_rot_error_deg.x(), 2) + ", " +
                                                        Fixed(m.mean_abs_rot_error_deg.y(), 2) + ", " +
                                                        Fixed(m.mean_abs_rot_error_deg.z(), 2)},
      {"map error, aligned mean / p95 (m)", Fixed(map_error.mean_m, 3) + " / " + Fixed(map_error.p95_m, 3)},
      {"first loop closure: height error odometry -> optimised (m)",
       loop_point ? "at " + Fixed(loop_point->time_s, 1) + " s: " + Fixed(loop_point->odometry.height_error_m, 3) +
                        " -> " + Fixed(loop_point->optimized.height_error_m, 3)
                  : (mapping.first_loop_closure_time_s < 0.0 ? "none (no loop closure)"
                                                             : "n/a (no pose within 0.1 s of it)")}};
  for (BenchmarkFigure& f : StageFigures(mapper.Times(), summary.processing_s)) figures.push_back(std::move(f));
  return figures;
}

// Output of a command run through the shell (all lines), and its exit status.
std::string Capture(const std::string& command, int* status) {
  std::FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    *status = -1;
    return "";
  }
  std::string out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
  *status = pclose(pipe);
  return out;
}

// The number under key in a JSON text (depth first, the first in file
// order), or NaN when there is none or the text is not JSON.
double FindNumber(const nlohmann::ordered_json& json, const std::string& key) {
  if (!json.is_object()) return std::nan("");
  for (const auto& [name, value] : json.items()) {
    if (name == key && value.is_number()) return value.get<double>();
    const double inner = FindNumber(value, key);
    if (!std::isnan(inner)) return inner;
  }
  return std::nan("");
}

double JsonNumber(const std::string& text, const std::string& key) {
  return FindNumber(nlohmann::ordered_json::parse(text, nullptr, false), key);
}

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// KITTI 00 frames 0-15 (real HDL-64 sweeps, no IMU): `unimap convert` then
// `unimap run` with the HDL-64 platform file (child processes on this
// process's core); KISS-ICP's C++ core on the same sweeps when its runner is built.
std::vector<BenchmarkFigure> RunKitti(const BenchOptions& options) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(options.kitti)) return {{"skipped", options.kitti + " not found"}};
  const fs::path work = fs::temp_directory_path() / ("unimap-bench-kitti-" + std::to_string(getpid()));
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{work};
  // This executable, even if its file was replaced since it started.
  const std::string self = "/proc/" + std::to_string(getpid()) + "/exe";
  int status = 0;
  Capture(
      "'" + self + "' convert --input '" + options.kitti + "' --format kitti --out '" + (work / "data").string() + "'",
      &status);
  if (status != 0) throw Error("unimap convert failed on " + options.kitti);
  const std::string platform = (fs::path(options.configs) / "platforms" / "kitti_hdl64.yaml").string();
  Capture("'" + self + "' run --quiet --threads 1 --platform '" + platform + "' --data '" + (work / "data").string() +
              "' --out '" + (work / "out").string() + "'",
          &status);
  if (status != 0) throw Error("unimap run failed on the converted " + options.kitti);
  const std::string run = ReadText(work / "out" / "run.json");
  const std::string metrics = ReadText(work / "out" / "metrics.json");
  const double scans = JsonNumber(run, "scans");
  const double processing_s = JsonNumber(run, "processing_s");
  std::vector<BenchmarkFigure> figures = {
      {"platform", platform},
      {"sweeps (matched)", Fixed(scans, 0) + " (" + Fixed(JsonNumber(run, "scans_matched"), 0) + ")"},
      {"unimap: sweeps per second (whole run: deskew, matching, map, loop search)", Fixed(scans / processing_s, 1)},
      {"unimap: ate_rmse_m / trajectory_scale",
       Fixed(JsonNumber(metrics, "ate_rmse_m"), 4) + " / " + Fixed(JsonNumber(metrics, "trajectory_scale"), 3)}};
  if (!fs::exists(options.kiss_icp)) {
    figures.push_back({"KISS-ICP", "not built (bash scripts/peer_kiss_icp.sh builds it)"});
    return figures;
  }
  const std::string out =
      Capture("'" + options.kiss_icp + "' '" + options.kitti + "' '" + (work / "kiss.tum").string() + "'", &status);
  const std::size_t line = out.find("kiss-icp:");
  figures.push_back(
      {"KISS-ICP C++ core (registration only, one thread)",
       status == 0 && line != std::string::npos ? out.substr(line, out.find('\n', line) - line) : "failed"});
  if (status == 0) {
    Capture("'" + self + "' evaluate --estimate '" + (work / "kiss.tum").string() + "' --truth '" +
                (work / "data" / "groundtruth.tum").string() + "' --out '" + (work / "kiss").string() + "'",
            &status);
    const std::string kiss_metrics = ReadText(work / "kiss" / "metrics.json");
    figures.push_back(
        {"KISS-ICP: ate_rmse_m / trajectory_scale", Fixed(JsonNumber(kiss_metrics, "ate_rmse_m"), 4) + " / " +
                                                        Fixed(JsonNumber(kiss_metrics, "trajectory_scale"), 3)});
  }
  return figures;
}

std::vector<BenchmarkCase> Cases() {
  return {
      {"simulate: tunnel, rotating Hokuyo",
       "`unimap simulate --scenario configs/scenarios/tunnel.yaml`: the paper's 15-minute tunnel "
       "fly-through with the rotating Hokuyo (40 lines/s x 1081 beams, every beam cast from the "
       "LiDAR pose at its own firing time), IMU at 200 Hz, encoder at 100 Hz, written to disk. "
       "Target: under 60 s.",
       [](const BenchOptions& o) { return SimulateScenario(o, "tunnel"); }},
      {"run: tunnel, rotating Hokuyo",
       "`unimap run` (the full mapper: deskew, GPF on every line, ESKF, submaps, pose graph, loop-closure "
       "search) on the simulated tunnel with the rotating Hokuyo. Targets: real-time factor >= 3 (issue 4), "
       ">= 2 (issue 5) on one core; drift_percent <= 1.0, each rotation error <= 0.2 deg, max errors below the "
       "paper's 2.0 / 0.37 / 1.11 m, map error mean <= 0.05 m.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "tunnel"); }},
      {"run: corridor loop, fixed VLP-16",
       "`unimap run` on the simulated corridor loop with the fixed VLP-16. Targets: real-time factor >= 2, at "
       "least one loop closure, ate_rmse_m <= 0.10, map error mean <= 0.05 m.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "corridor_loop"); }},
      {"run: patio, rotating VLP-16",
       "`unimap run` on the simulated patio with the VLP-16 on a motor at 30 rpm (distance map 0.3 m, 40 m box). "
       "Targets: real-time factor >= 2, ate_rmse_m <= 0.15.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "patio"); }},
      {"run: narrow hallway, rotating Hokuyo",
       "`unimap run` on the simulated 1.1 m-wide hallway loop walked at 0.5 m/s with the rotating Hokuyo. "
       "Targets: real-time factor >= 2, ate_rmse_m <= 0.10.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "narrow_hallway"); }},
      {"run: patio, fixed VLP-16 (robustness matrix)",
       "The robustness matrix's slowest pair while it mapped at the platform's 0.1 m (docs/robustness.md); it now "
       "maps at 0.3 m, the scene's scale (docs/mapping.md, \"Seventh round\"): `unimap run` with the fixed "
       "VLP-16's platform file on the simulated patio. Target (issue 20): real-time factor >= 5.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "patio", "fixed_vlp16"); }},
      {"run: patio, rotating Hokuyo (robustness matrix)",
       "The robustness matrix's slowest pair: `unimap run` with the rotating Hokuyo's platform file on the "
       "simulated patio. Target (issue 20): real-time factor >= 5.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "patio", "rotating_hokuyo"); }},
      {"run: tunnel, fixed VLP-16 (robustness matrix)",
       "The robustness matrix's second slowest pair: `unimap run` with the fixed VLP-16's platform file on the "
       "simulated tunnel (its dataset takes about 5 GB of temporary space while it runs). Target (issue 20): "
       "real-time factor >= 5.",
       [](const BenchOptions& o) { return LocalizeScenario(o, "tunnel", "fixed_vlp16"); }},
      {"run: KITTI 00 frames 0-15, HDL-64, beside KISS-ICP",
       "`unimap convert` and `unimap run --platform configs/platforms/kitti_hdl64.yaml` on the real KITTI 00 sweeps "
       "0-15 (../shared/data/kitti00, 120k points each, no IMU: constant-velocity prior), and KISS-ICP's C++ core "
       "(defaults, one thread; built by scripts/peer_kiss_icp.sh) on the same sweeps in the same session. Targets "
       "(issue 20): >= 20 sweeps/s; ATE <= 0.36 m.",
       [](const BenchOptions& o) { return RunKitti(o); }},
  };
}

// First "model name" of /proc/cpuinfo, or "unknown".
std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

// Output of a shell command (first line), or "" when it fails.
std::string CommandOutput(const std::string& command) {
  std::FILE* pipe = popen((command + " 2>/dev/null").c_str(), "r");
  if (pipe == nullptr) return "";
  char buffer[256];
  std::string out;
  if (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out = buffer;
  const int status = pclose(pipe);
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return status == 0 ? out : "";
}

std::string GitCommit() {
  std::string commit = CommandOutput("git rev-parse HEAD");
  if (commit.empty()) return "unknown";
  if (!CommandOutput("git status --porcelain --untracked-files=no").empty()) commit += " (with uncommitted changes)";
  return commit;
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// Keeps this process on the CPU it runs on: every figure is for one core.
bool PinToOneCore() {
  const int cpu = sched_getcpu();
  if (cpu < 0) return false;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return sched_setaffinity(0, sizeof set, &set) == 0;
}

void WriteAtomically(const std::filesystem::path& file, const std::string& text) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::trunc);
    out << text;
    if (!out.flush()) throw InputError(partial.string() + ": cannot write");
  }
  std::filesystem::rename(partial, file);
}

int RunBench(const BenchOptions& options) {
  const bool pinned = PinToOneCore();
  std::ostringstream md;
  md << "# Benchmarks\n\n"
     << "Generated by `unimap bench" << (options.quick ? " --quick" : "") << "`; do not edit by hand, rerun "
     << "it to refresh. Every figure is measured on one core (the process is pinned to one CPU). Stage times are "
     << "wall time spent in each stage; the map thread runs beside the main thread on the same core, so the "
     << "shares overlap and may add up to more than 100 %.\n\n"
     << "| | |\n|---|---|\n"
     << "| machine | " << CpuModel() << ", " << std::thread::hardware_concurrency() << " cores"
     << (pinned ? ", run pinned to one" : ", NOT pinned (sched_setaffinity failed)") << " |\n"
     << "| commit | " << GitCommit() << " |\n"
     << "| date | " << UtcNow() << " |\n"
     << "| mode | " << (options.quick ? "quick (simulations cut to 60 s of data)" : "full") << " |\n";
  int failures = 0;
  for (const BenchmarkCase& c : Cases()) {
    std::cout << "running: " << c.name << " ..." << std::flush;
    md << "\n## " << c.name << "\n\n" << c.description << "\n\n";
    try {
      const std::vector<BenchmarkFigure> figures = c.run(options);
      md << "| figure | value |\n|---|---|\n";
      for (const BenchmarkFigure& f : figures) md << "| " << f.name << " | " << f.value << " |\n";
      std::cout << " done\n";
      for (const BenchmarkFigure& f : figures) std::cout << "  " << f.name << ": " << f.value << '\n';
    } catch (const std::exception& e) {
      ++failures;
      md << "**failed:** " << e.what() << "\n";
      std::cout << " FAILED: " << e.what() << '\n';
    }
  }
  WriteAtomically(options.out, md.str());
  std::cout << "wrote " << options.out << '\n';
  return failures == 0 ? 0 : 1;
}

}  // namespace

void AddBenchCommand(CLI::App* app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd = app->add_subcommand("bench", "Run the speed benchmarks and rewrite docs/benchmarks.md");
  cmd->add_option("--out", options->out, "Report to write (default docs/benchmarks.md)");
  cmd->add_option("--configs", options->configs, "Folder holding scenarios/ and platforms/ (default configs)")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--quick", options->quick, "Short runs (60 s of simulated data) for a smoke test");
  cmd->add_option("--kitti", options->kitti,
                  "KITTI-style folder for the real-data case (default ../shared/data/kitti00)");
  cmd->add_option("--kiss-icp", options->kiss_icp, "KISS-ICP runner to compare with (scripts/peer_kiss_icp.sh)");
  auto matrix = std::make_shared<MatrixOptions>();
  auto run_matrix = std::make_shared<bool>(false);
  cmd->add_flag("--matrix", *run_matrix,
                "Run the robustness matrix instead (every scenario x payload, 2x speed, noisy IMU) and rewrite the "
                "table in docs/robustness.md");
  cmd->add_option("--jobs", matrix->jobs, "Matrix: cases at once, each pinned to its own core (default 1)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--seed", matrix->seed, "Matrix: simulation seed of every case (default: each scenario's own)");
  cmd->add_option("--work-dir", matrix->work_dir,
                  "Matrix: keep datasets and runs here and reuse datasets found there (default: temporary)");
  cmd->add_option("--max-duration-s", matrix->max_duration_s, "Matrix: only the first seconds of each case")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--only", matrix->only, "Matrix: only cases whose name contains this text");
  cmd->callback([options, matrix, run_matrix, cmd]() {
    if (*run_matrix) {
      matrix->configs = options->configs;
      if (cmd->count("--out") > 0) matrix->out = options->out;
      const int code = RunRobustnessMatrix(*matrix);
      if (code != 0) throw CLI::RuntimeError(code);
      return;
    }
    const int code = RunBench(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
