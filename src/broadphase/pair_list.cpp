#include "broadphase/pair_list.hpp"

#include <algorithm>

namespace tridem {

void exclusive_scan(const std::vector<std::int64_t>& counts, std::size_t n,
                    std::vector<std::int64_t>& offset) {
  offset.resize(n + 1);
  offset[0] = 0;
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + counts[i];
}

void build_reverse_index(const PairList& pairs, std::size_t n, bool parallel,
                         ReverseIndex& out) {
  on_team(parallel, [&] {
    const auto n_emitters = static_cast<std::int64_t>(pairs.offset.size()) - 1;
    const std::int64_t count = pairs.count();
    team_single([&] { out.cursor.assign(n, 0); });
    // Count how often each particle is a partner.
#pragma omp for schedule(static)
    for (std::int64_t s = 0; s < count; ++s) {
#pragma omp atomic
      ++out.cursor[pairs.partner[s]];
    }
    team_single([&] {
      exclusive_scan(out.cursor, n, out.offset);
      grow_to(out.slot, count);
      std::copy(out.offset.begin(), out.offset.end() - 1, out.cursor.begin());
    });
#pragma omp for schedule(static)
    for (std::int64_t e = 0; e < n_emitters; ++e) {
      for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
        std::int64_t at;
#pragma omp atomic capture
        at = out.cursor[pairs.partner[s]]++;
        out.slot[at] = s;
      }
    }
    // The atomic fill order depends on scheduling; sorting makes it deterministic.
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t p = 0; p < static_cast<std::int64_t>(n); ++p)
      sort_row(out.slot.data(), out.offset[p], out.offset[p + 1]);
  });
}

}  // namespace tridem
