#include "interrupt.hpp"

#include <csignal>

namespace tridem::app {

namespace {

// A lock-free atomic is async-signal-safe to store to from a handler.
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<int> g_interrupt{0};

extern "C" void on_signal(int signal) { g_interrupt.store(signal); }

void install(int signal) {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal is not caught
  sigaction(signal, &action, nullptr);
}

}  // namespace

const std::atomic<int>& install_interrupt_handlers() {
  install(SIGINT);
  install(SIGTERM);
  return g_interrupt;
}

int exit_code_for_signal(int signal) { return 128 + signal; }

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace tridem::app
