#pragma once
// Clean stops of the long commands (run, localize, simulate, convert, demo)
// on SIGINT, SIGTERM and SIGHUP.
#include <atomic>

namespace unimap::cli {

// While a SignalGuard lives, the first SIGINT, SIGTERM or SIGHUP only sets
// StopFlag(), which the long loops poll (RunDataset's stop, the simulator,
// the converters): the command then writes what it processed, completely,
// and exits with ExitCode() = 128 + the signal (130, 143, 129). A second
// signal ends the process at once with the signal's default action.
// Destruction restores the handlers that were there before.
class SignalGuard {
 public:
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

  // Set by the first signal; never cleared while the guard lives.
  static const std::atomic<bool>& StopFlag();
  // The first signal received since the guard was made; 0 if none.
  static int Received();
  // 128 + Received() when a signal arrived, else code.
  static int ExitCode(int code);
};

}  // namespace unimap::cli
