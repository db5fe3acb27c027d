#pragma once
// Candidate pairs in compressed-row form, grouped by the particle that emits them: the
// pairs of emitter i are partner[offset[i] .. offset[i+1]), partners ascending. Every pair
// appears once. Grouping by emitter lets each pair find its contact history of the
// previous step in the emitter's old row, and keeps the order deterministic.
#include "broadphase/row_sort.hpp"
#include "core/omp_team.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tridem {

struct PairList {
  std::vector<std::int64_t> offset;   ///< n + 1 entries
  std::vector<std::int32_t> partner;  ///< capacity may exceed count()

  std::int64_t count() const { return offset.empty() ? 0 : offset.back(); }
};

/// For each particle, the pairs in which it is the partner: slot[rev_offset[p] ..
/// rev_offset[p+1]) index PairList::partner, ascending.
struct ReverseIndex {
  std::vector<std::int64_t> offset;
  std::vector<std::int64_t> slot;
  std::vector<std::int64_t> cursor;  ///< scratch for filling
};

/// Builds the reverse index of `pairs` over n particles. Team code (core/omp_team.hpp):
/// on the caller's team inside one, else on a region of its own when `parallel`.
void build_reverse_index(const PairList& pairs, std::size_t n, bool parallel,
                         ReverseIndex& out);

/// Sorts v[begin, end) ascending: insertion sort for the usual short rows, std::sort for
/// the long rows of walls touching many particles.
template <class T>
inline void sort_row(T* v, std::int64_t begin, std::int64_t end) {
  if (end - begin > 32) {
    std::sort(v + begin, v + end);
    return;
  }
  insertion_sort(v, begin, end);
}

/// Makes room for `needed` entries, with 20% headroom so that a slowly growing pair count
/// reallocates rarely; never shrinks. The only allocation in a running time loop.
template <class Vec>
inline void grow_to(Vec& v, std::int64_t needed) {
  if (v.size() < static_cast<std::size_t>(needed))
    v.resize(static_cast<std::size_t>(needed + needed / 5 + 16));
}

/// Exclusive prefix sum of counts[0..n) into offset[0..n], offset[0] = 0.
void exclusive_scan(const std::vector<std::int64_t>& counts, std::size_t n,
                    std::vector<std::int64_t>& offset);

/// Fills `pairs` with the rows of n emitters: visit_row(i, emit) calls emit(j) for every
/// partner j of emitter i, the same ones each time. It runs twice, to count each row
/// (into `row_count`, n entries) and then to fill it, so that every row has its own place
/// whatever the thread that computes it; rows are then sorted by partner. Team code
/// (core/omp_team.hpp): on the caller's team inside one, else on a region of its own when
/// `parallel`.
template <class VisitRow>
void fill_rows(std::size_t n, bool parallel, std::vector<std::int64_t>& row_count,
               PairList& pairs, VisitRow&& visit_row) {
  on_team(parallel, [&] {
    const auto rows = static_cast<std::int64_t>(n);
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < rows; ++i) {
      std::int64_t count = 0;
      visit_row(static_cast<std::int32_t>(i), [&count](std::int32_t) { ++count; });
      row_count[i] = count;
    }
    team_single([&] {
      exclusive_scan(row_count, n, pairs.offset);
      grow_to(pairs.partner, pairs.count());
    });
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < rows; ++i) {
      std::int64_t at = pairs.offset[i];
      visit_row(static_cast<std::int32_t>(i), [&](std::int32_t j) { pairs.partner[at++] = j; });
      sort_row(pairs.partner.data(), pairs.offset[i], pairs.offset[i + 1]);
    }
  });
}

}  // namespace tridem
