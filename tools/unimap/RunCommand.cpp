// `unimap run`: localise a dataset (odometry mode), write the trajectory,
// run.json and, with ground truth, the evaluation.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "RunOutputs.hpp"
#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Localizer.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

struct RunCliOptions {
  std::string platform_file;    // platform YAML
  std::string data_dir;         // dataset folder
  std::string out_dir;          // output folder
  double max_duration_s = 0.0;  // 0: the whole dataset
  int threads = 1;              // GPF threads
  bool quiet = false;           // no progress line
};

int RunRun(const RunCliOptions& options) {
  try {
    const Platform platform = LoadPlatform(options.platform_file);
    pipeline::LocalizerOptions localizer_options =
        pipeline::LocalizerOptions::FromPlatform(CoreParameters::FromMap(platform.parameters));
    localizer_options.gpf.threads = options.threads;
    io::DatasetReader reader(options.data_dir);
    if (!reader.metadata().payload.empty() && reader.metadata().payload != platform.plugin.plugin->Name()) {
      std::cerr << "warning: dataset was recorded for payload '" << reader.metadata().payload
                << "', platform uses '" << platform.plugin.plugin->Name() << "'\n";
    }
    const std::filesystem::path out(options.out_dir);
    pipeline::Localizer localizer(localizer_options, platform.plugin.plugin);
    const pipeline::RunSummary summary =
        RunLocalizerToFolder(reader, localizer, out, options.max_duration_s, options.quiet);

    RunOutputsInput outputs;
    outputs.out_dir = out;
    outputs.platform_file = options.platform_file;
    outputs.payload = platform.plugin.plugin->Name();
    outputs.data_dir = options.data_dir;
    outputs.gpf_threads = static_cast<std::size_t>(options.threads);
    outputs.summary = summary;
    outputs.stats = localizer.stats();
    outputs.has_groundtruth = reader.has_groundtruth();
    return WriteRunOutputs(outputs);
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddRunCommand(CLI::App* app) {
  auto options = std::make_shared<RunCliOptions>();
  CLI::App* cmd = app->add_subcommand("run", "Localise a dataset with a platform (odometry mode) and evaluate it");
  cmd->add_option("--platform", options->platform_file, "Platform YAML")->required()->check(CLI::ExistingFile);
  cmd->add_option("--data", options->data_dir, "Dataset folder (docs/dataset-format.md)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", options->out_dir, "Output folder")->required();
  cmd->add_option("--max-duration-s", options->max_duration_s, "Process only this much data (s)");
  cmd->add_option("--threads", options->threads, "Threads for particle weighting")->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", options->quiet, "No progress line");
  cmd->callback([options]() {
    const int code = RunRun(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
