// `unimap convert`: KITTI, CARMEN, ROS 1 and ROS 2 bag data into the dataset format.
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "OutputFolder.hpp"
#include "RecordingOptions.hpp"
#include "SignalGuard.hpp"
#include "io/DatasetConversion.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

void PrintReport(const std::string& format, const io::ConversionReport& report, std::ostream& out) {
  out << "converted " << format << " -> payload " << report.payload << '\n'
      << "  scans:        " << report.scans << '\n'
      << "  imu:          " << report.imu << '\n'
      << "  encoder:      " << report.encoder << '\n'
      << "  odometry:     " << report.odometry << '\n'
      << "  ground truth: " << report.groundtruth << '\n';
  if (report.dropped_points > 0) out << "  points dropped (non-finite): " << report.dropped_points << '\n';
  if (!report.skipped.empty()) {
    out << "  skipped:\n";
    for (const auto& [reason, count] : report.skipped) out << "    " << count << "  " << reason << '\n';
  }
  for (const std::string& note : report.notes) out << "  note: " << note << '\n';
}

int RunConvert(RecordingOptions options, const std::filesystem::path& output) {
  try {
    io::ConversionOptions c = options.Resolved();
    c.output = output;
    c.stop = &SignalGuard::StopFlag();
    PrepareOutputFolder(c.output, "--out");
    const io::ConversionReport report = io::Convert(options.format, c);
    PrintReport(options.format, report, std::cout);
    if (report.interrupted) {
      std::cout << "interrupted (signal " << SignalGuard::Received()
                << "): the dataset holds the messages read before, complete\n";
    }
    std::cout << "wrote " << c.output.string() << '\n';
    if (report.scans == 0 && !report.interrupted) {
      // An empty conversion is no success: nothing in it can be mapped.
      std::cerr << "error: " << c.input.string() << ": no scan converted: the dataset written holds none"
                << " (see the counts and notes above)\n";
      return 2;
    }
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {  // e.g. std::filesystem errors on the output folder
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddConvertCommand(CLI::App* app) {
  auto options = std::make_shared<RecordingOptions>();
  auto output = std::make_shared<std::filesystem::path>();
  CLI::App* cmd =
      app->add_subcommand("convert", "Convert KITTI, CARMEN, ROS 1 or ROS 2 bag data into a unimap dataset folder");
  cmd->add_option("--input", options->conversion.input,
                  "KITTI sequence folder, CARMEN log (.clf, .clf.bz2), ROS 1 bag, or ROS 2 bag folder (or .db3)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--format", options->format, "Input format")
      ->required()
      ->check(CLI::IsMember({"kitti", "carmen", "rosbag", "ros2"}));
  cmd->add_option("--out", *output, "Dataset folder to write")->required();
  AddRecordingOptions(cmd, options.get());
  cmd->callback([options, output]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: stop reading, finish the dataset, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunConvert(*options, *output));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
