#include "core/progress.hpp"

#include <fmt/format.h>
#include <string>
#include <unistd.h>

namespace tridem {

namespace {

std::string clock_time(double seconds) {
  const auto s = static_cast<long long>(seconds + 0.5);
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

}  // namespace

bool is_terminal(std::FILE* stream) { return isatty(fileno(stream)) != 0; }

ProgressBar::ProgressBar(std::int64_t total, bool enabled, std::FILE* stream,
                         double quiet_seconds)
    : total_(total), enabled_(enabled), stream_(stream), quiet_seconds_(quiet_seconds),
      start_(Clock::now()), last_draw_(start_) {}

void ProgressBar::update(std::int64_t done) {
  if (!enabled_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Short runs stay quiet; then a few redraws a second are plenty.
  if (elapsed < quiet_seconds_) return;
  if (drawn_ && std::chrono::duration<double>(now - last_draw_).count() < 0.25) return;
  last_draw_ = now;
  const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1;
  const double rate = static_cast<double>(done) / elapsed;
  const double left = rate > 0 ? static_cast<double>(total_ - done) / rate : 0;
  constexpr int width = 30;
  const int filled = static_cast<int>(fraction * width);
  fmt::print(stream_, "\r[{:=<{}}{: <{}}] {:5.1f}%  {}/{} steps  {:.4g} steps/s  {} left ",
             "", filled, "", width - filled, 100 * fraction, done, total_, rate,
             clock_time(left));
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!drawn_) return;
  fmt::print(stream_, "\r{: <100}\r", "");
  std::fflush(stream_);
  drawn_ = false;
}

}  // namespace tridem
