#include "io/output/colormap.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tridem::io {
namespace {

constexpr Rgb hex(unsigned v) {
  return {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0};
}

// Viridis sampled at nine evenly spaced points; linear interpolation between them stays
// within a few percent of the full map, and keeps lightness monotonic.
constexpr std::array<Rgb, 9> kSequential = {hex(0x440154), hex(0x472d7b), hex(0x3b528b),
                                            hex(0x2c728e), hex(0x21918c), hex(0x28ae80),
                                            hex(0x5ec962), hex(0xaddc30), hex(0xfde725)};

// Saturated hues in an order where neighbours differ strongly; no greys, so walls stand out.
constexpr std::array<Rgb, 12> kCategorical = {
    hex(0x1f6fb4), hex(0xf28e1c), hex(0x2ca02c), hex(0xd62728), hex(0x9467bd), hex(0x8c564b),
    hex(0xe377c2), hex(0xbcbd22), hex(0x17becf), hex(0x0b3d91), hex(0xffd92f), hex(0x66a61e)};

}  // namespace

Rgb sequential_color(double t) {
  if (!(t > 0)) t = 0;  // also maps NaN to the low end
  t = std::min(t, 1.0);
  const double position = t * (kSequential.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(position), kSequential.size() - 2);
  const double f = position - static_cast<double>(k);
  const Rgb a = kSequential[k], b = kSequential[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

Rgb categorical_color(int index) {
  const auto n = static_cast<int>(kCategorical.size());
  return kCategorical[static_cast<std::size_t>(((index % n) + n) % n)];
}

}  // namespace tridem::io
