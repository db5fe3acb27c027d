// Snapshot::resize: the arrays are sized side by side, each by one thread. A snapshot
// that grows (the first of a run) zeroes them all, and at 10^7 triangles that is some
// 1.5 GB written, and paged in, by one core while the GPU or the stepping waits.
#include "tridem/snapshot.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace tridem {

void Snapshot::resize(std::size_t n) {
  std::vector<std::function<void()>> resizes;
  for_each_particle_array(*this,
                          [&](auto& v, auto&) { resizes.emplace_back([&v, n] { v.resize(n); }); });
  const auto count = static_cast<std::ptrdiff_t>(resizes.size());
  const bool grows = n > x.size();
#pragma omp parallel for schedule(dynamic, 1) if (grows && n > 65536)
  for (std::ptrdiff_t k = 0; k < count; ++k) resizes[static_cast<std::size_t>(k)]();
}

}  // namespace tridem
