// unimap: real-time 3D mapping from any LiDAR payload (command line).
#include <cstdlib>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "CommandLine.hpp"
#include "Commands.hpp"
#include "unimap/Version.hpp"

namespace {

// Keeps freed memory in the process, in one heap, for reuse instead of returning it to
// the system: a mapper frees and reallocates megabytes per sweep (deskewed
// points, downsampling tables, map blocks), and glibc's defaults give them
// back and fault them in again each time (docs/mapping.md, "Third round").
// Process-wide, so the command line sets it; the library does not.
void ConfigureAllocator() {
#if defined(__GLIBC__)
  constexpr int kTrimThresholdBytes = 64 << 20;  // free memory kept at the top of a heap before it is returned
  constexpr int kMmapThresholdBytes = 32 << 20;  // larger blocks are mapped (and unmapped) on their own
  mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes);
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
  // One heap for every thread: glibc otherwise gives each allocating thread
  // (the submaps' distance-map workers, the pose-graph optimiser) a heap of
  // its own, each keeping what it freed, so the process holds the sum of
  // their high-water marks although they never peak together (measured in
  // docs/reliability.md, memory over long runs). An explicit
  // MALLOC_ARENA_MAX wins.
  if (std::getenv("MALLOC_ARENA_MAX") == nullptr) mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  ConfigureAllocator();
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
  unimap::cli::AddCalibrateCommand(&app);
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
