#include "anvil/core/interrupt.h"

#include "anvil/core/processes.h"

#include <csignal>
#include <unistd.h>

namespace anvil::interrupt {
namespace {

volatile std::sig_atomic_t first_signal = 0;

extern "C" void on_signal(int signal) {
  if (first_signal == 0) {
    first_signal = signal;
    return;
  }
  // Only async-signal-safe calls here.
  constexpr char message[] = "anvil: stopped at once (second interrupt); the last checkpoint is kept\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(128 + signal);
}

} // namespace

void install() {
  struct sigaction action = {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGUSR1, &action, nullptr);
}

int received() {
  return first_signal;
}

int requested() {
  return processes::maximum(first_signal);
}

const char* name(int signal) {
  return signal == SIGINT    ? "SIGINT"
         : signal == SIGTERM ? "SIGTERM"
         : signal == SIGUSR1 ? "SIGUSR1 (Ctrl-C or SIGTERM passed on by anvil run to its processes)"
                             : "a signal";
}

} // namespace anvil::interrupt
