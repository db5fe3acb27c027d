#include "io/output/base64.hpp"

#include "tridem/error.hpp"

#include <fmt/format.h>

#include <array>

namespace tridem::io {
namespace {

constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr int kPad = 64;
constexpr int kInvalid = -1;

constexpr std::array<int, 256> make_values() {
  std::array<int, 256> values{};
  values.fill(kInvalid);
  for (std::size_t k = 0; k < kAlphabet.size(); ++k)
    values[static_cast<unsigned char>(kAlphabet[k])] = static_cast<int>(k);
  values['='] = kPad;
  return values;
}
constexpr auto kValues = make_values();

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

void base64_append(std::span<const std::uint8_t> bytes, std::string& out) {
  const std::size_t start = out.size();
  out.resize(start + (bytes.size() + 2) / 3 * 4);
  char* const first = out.data() + start;
  // Each group of three bytes is four characters of its own: a frame's hundreds of
  // megabytes are encoded on the OpenMP threads.
  const auto groups = static_cast<std::ptrdiff_t>(bytes.size() / 3);
  constexpr std::ptrdiff_t kParallelGroups = std::ptrdiff_t{1} << 16;
#pragma omp parallel for schedule(static) if (groups >= kParallelGroups)
  for (std::ptrdiff_t g = 0; g < groups; ++g) {
    const std::size_t k = 3 * static_cast<std::size_t>(g);
    const std::uint32_t v =
        (std::uint32_t{bytes[k]} << 16) | (std::uint32_t{bytes[k + 1]} << 8) | bytes[k + 2];
    char* to = first + 4 * static_cast<std::size_t>(g);
    to[0] = kAlphabet[(v >> 18) & 63];
    to[1] = kAlphabet[(v >> 12) & 63];
    to[2] = kAlphabet[(v >> 6) & 63];
    to[3] = kAlphabet[v & 63];
  }
  const std::size_t k = 3 * static_cast<std::size_t>(groups);
  char* to = first + 4 * static_cast<std::size_t>(groups);
  const std::size_t rest = bytes.size() - k;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t{bytes[k]} << 16;
    if (rest == 2) v |= std::uint32_t{bytes[k + 1]} << 8;
    *to++ = kAlphabet[(v >> 18) & 63];
    *to++ = kAlphabet[(v >> 12) & 63];
    *to++ = rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    *to++ = '=';
  }
}

std::string base64_encode(std::span<const std::uint8_t> bytes) {
  std::string out;
  base64_append(bytes, out);
  return out;
}

std::vector<std::uint8_t> base64_decode(std::string_view text, std::string_view what) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  std::array<int, 4> group{};
  int filled = 0;
  for (const char c : text) {
    if (is_space(c)) continue;
    const int v = kValues[static_cast<unsigned char>(c)];
    if (v == kInvalid) throw Error(fmt::format("{}: invalid base64 character '{}'", what, c));
    group[filled++] = v;
    if (filled < 4) continue;
    filled = 0;
    // Padding may only fill the last one or two places of a group.
    const int data = group[0] == kPad || group[1] == kPad ? -1
                     : group[2] == kPad                   ? (group[3] == kPad ? 1 : -1)
                     : group[3] == kPad                   ? 2
                                                          : 3;
    if (data < 0) throw Error(fmt::format("{}: misplaced base64 padding", what));
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k)
      bits = (bits << 6) | static_cast<std::uint32_t>(group[k] == kPad ? 0 : group[k]);
    out.push_back(static_cast<std::uint8_t>(bits >> 16));
    if (data > 1) out.push_back(static_cast<std::uint8_t>(bits >> 8));
    if (data > 2) out.push_back(static_cast<std::uint8_t>(bits));
  }
  if (filled != 0) throw Error(fmt::format("{}: truncated base64 data", what));
  return out;
}

}  // namespace tridem::io
