#pragma once
// A one-line progress bar with rate and time left, drawn on a terminal only, and only for
// runs that last more than a moment. No library on Debian does this for C++; it is small.
#include <chrono>
#include <cstdint>
#include <cstdio>

namespace tridem {

class ProgressBar {
 public:
  /// Nothing is drawn before `quiet_seconds` have passed: short runs stay silent.
  ProgressBar(std::int64_t total, bool enabled, std::FILE* stream = stderr,
              double quiet_seconds = 2.0);
  /// Redraws at most a few times a second.
  void update(std::int64_t done);
  /// Clears the line.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::int64_t total_;
  bool enabled_;
  bool drawn_ = false;
  std::FILE* stream_;
  double quiet_seconds_;
  Clock::time_point start_, last_draw_;
};

/// True when the stream is an interactive terminal.
bool is_terminal(std::FILE* stream);

}  // namespace tridem
