#include "live/client_message.hpp"

#include <charconv>
#include <fmt/format.h>

namespace tridem::live {

namespace {

ClientMessage invalid(std::string why) {
  ClientMessage m;
  m.error = std::move(why);
  return m;
}

/// A whole number in [lo, hi] written in decimal digits only (no sign, no spaces).
bool parse_number(std::string_view text, long long lo, long long hi, long long& out) {
  if (text.empty() || text.size() > 12) return false;
  for (char c : text)
    if (c < '0' || c > '9') return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && out >= lo && out <= hi;
}

/// Printable ASCII only, so that a log line quoting a refused message stays one line.
std::string printable(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 32)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out;
}

}  // namespace

ClientMessage parse_client_message(std::string_view text) {
  if (text.size() > kMaxCommandBytes)
    return invalid(fmt::format("message of {} bytes (at most {})", text.size(), kMaxCommandBytes));
  const std::size_t space = text.find(' ');
  const std::string_view word = text.substr(0, space);
  const std::string_view arg =
      space == std::string_view::npos ? std::string_view() : text.substr(space + 1);
  ClientMessage m;
  using K = ClientMessage::Kind;
  const bool bare = space == std::string_view::npos;
  if (word == "next" && bare)
    m.kind = K::Next;
  else if (word == "pause" && bare)
    m.kind = K::Pause;
  else if (word == "resume" && bare)
    m.kind = K::Resume;
  else if (word == "step" && bare)
    m.kind = K::Step;
  else if (word == "fps" && !bare) {
    if (!parse_number(arg, kMinFps, kMaxFps, m.value))
      return invalid(fmt::format("fps wants a whole number from {} to {}, got '{}'", kMinFps,
                                 kMaxFps, printable(arg)));
    m.kind = K::Fps;
  } else if (word == "seek" && !bare) {
    if (!parse_number(arg, 0, 1'000'000'000, m.value))
      return invalid(fmt::format("seek wants a frame number, got '{}'", printable(arg)));
    m.kind = K::Seek;
  } else {
    return invalid(fmt::format("unknown command '{}'", printable(text)));
  }
  return m;
}

}  // namespace tridem::live
