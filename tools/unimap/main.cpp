// unimap: real-time 3D mapping from any LiDAR payload (command line).
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "CommandLine.hpp"
#include "Commands.hpp"
#include "unimap/Version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"unimap: real-time 3D mapping from any LiDAR payload (fixed 3D, rotating 3D, rotating 2D)"};
  app.set_version_flag("--version", std::string("unimap ") + unimap::kSdkVersion);
  app.require_subcommand(1);
  unimap::cli::AddPluginsCommand(&app);
  unimap::cli::AddConfigCommand(&app);
  unimap::cli::AddSimulateCommand(&app);
  unimap::cli::AddEvaluateCommand(&app);
  unimap::cli::AddRunCommand(&app);
  unimap::cli::AddLocalizeCommand(&app);
  unimap::cli::AddConvertCommand(&app);
  unimap::cli::AddBenchCommand(&app);
  unimap::cli::AddDemoCommand(&app);
  unimap::cli::AddReportCommand(&app);
  unimap::cli::SetCommandLine(argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    // The last resort: the commands report their own errors; an exception
    // reaching here is a bug, but still a message and an exit code, not an abort.
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
