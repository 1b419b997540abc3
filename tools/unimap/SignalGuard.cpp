#include "SignalGuard.hpp"

#include <csignal>

namespace unimap::cli {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Lock-free atomics: safe to touch from a signal handler.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
struct sigaction g_previous[3];

extern "C" void OnStopSignal(int signal) {
  int none = 0;
  if (!g_signal.compare_exchange_strong(none, signal)) {
    // The second signal: the user insists; stop now with the default action.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_stop.store(true);
}

}  // namespace

SignalGuard::SignalGuard() {
  g_stop.store(false);
  g_signal.store(0);
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress carry on
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &g_previous[i]);
}

SignalGuard::~SignalGuard() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

const std::atomic<bool>& SignalGuard::StopFlag() { return g_stop; }

int SignalGuard::Received() { return g_signal.load(); }

int SignalGuard::ExitCode(int code) {
  const int signal = Received();
  return signal != 0 ? 128 + signal : code;
}

}  // namespace unimap::cli
