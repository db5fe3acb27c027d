// Snapshot::resize: the arrays are sized side by side, each by one thread. A snapshot
// that grows (the first of a run) zeroes them all, and at 10^7 triangles that is some
// 1.5 GB written, and paged in, by one core while the GPU or the stepping waits.
#include "tridem/snapshot.hpp"

#include <cstddef>
#include <vector>

namespace tridem {

void Snapshot::resize(std::size_t n) {
  std::vector<std::vector<double>*> reals;
  for_each_field([&](auto field) {
    for_each_array(column(field), [&reals](std::vector<double>& v, int) { reals.push_back(&v); });
  });
  for (auto* v : {&x1, &y1, &x2, &y2, &x3, &y3, &mass, &inertia}) reals.push_back(v);
  const auto count = static_cast<std::ptrdiff_t>(reals.size()) + 2;
  const bool grows = n > x.size();
#pragma omp parallel for schedule(dynamic, 1) if (grows && n > 65536)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    if (k < count - 2)
      reals[static_cast<std::size_t>(k)]->resize(n);
    else if (k == count - 2)
      material.resize(n);
    else
      motion.resize(n);
  }
}

}  // namespace tridem
