#pragma once
// Ctrl-C and kill: SIGINT and SIGTERM set a flag that the run loop polls between chunks
// of steps, so the run stops at a step boundary and writes a checkpoint instead of dying
// mid-write. A second signal of the same kind acts as usual (the handler is one-shot), so
// a run that does not stop can still be killed.
#include <atomic>
#include <string>

namespace tridem::app {

/// Installs the handlers; returns the flag they set to the signal's number.
const std::atomic<int>& install_interrupt_handlers();

/// The conventional exit status of a process ended by `signal`: 128 + its number
/// (130 for SIGINT, 143 for SIGTERM).
int exit_code_for_signal(int signal);

/// "SIGINT", "SIGTERM", or "signal N".
std::string signal_name(int signal);

}  // namespace tridem::app
