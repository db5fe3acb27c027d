#include "decomposition/decomposed_pairs.hpp"

#include "broadphase/candidate_pairs.hpp"

#include <algorithm>

namespace tridem {

template <class Real>
DecomposedPairs<Real>::DecomposedPairs(const DecompositionSettings& settings,
                                       const std::vector<double>& longest_edge,
                                       const std::vector<Motion>& motion, ContactFilter filter)
    : filter_(filter),
      small_(classify_for_grid(longest_edge, motion).small),
      free_(motion.size()),
      decomposition_(settings, classify_for_grid(longest_edge, motion).cell, small_),
      row_count_(motion.size()),
      run_start_(motion.size()) {
  for (std::size_t i = 0; i < motion.size(); ++i) free_[i] = motion[i] == Motion::Free;
}

template <class Real>
template <class Emit>
void DecomposedPairs<Real>::visit_pairs(std::int32_t i, ParticleRange staged,
                                        const TriangleArrays<Real>& g,
                                        const physics::PeriodicFrame* periodic, Emit&& emit) const {
  const EmitterTest<Real> passes(g, i, small_.data(), free_.data(), filter_, periodic);
  auto consider = [&](std::int32_t j) {
    if (passes(j)) emit(j);
  };
  // Staged particles are ascending: those after i are its partners among the small ones.
  for (auto it = std::upper_bound(staged.begin(), staged.end(), i); it != staged.end(); ++it)
    consider(*it);
  for (const std::int32_t j : decomposition_.large()) consider(j);
}

template <class Real>
void DecomposedPairs<Real>::find(const double* x, const double* y, const TriangleArrays<Real>& g,
                                 bool parallel, PairList& pairs,
                                 const physics::PeriodicFrame* periodic) {
  decomposition_.update({x, y, g.lo_x, g.lo_y, g.hi_x, g.hi_y}, parallel, periodic);
  const Decomposition<Real>& d = decomposition_;
  const int domains = d.count();
  if (found_.size() < static_cast<std::size_t>(domains))
    found_.resize(static_cast<std::size_t>(domains));
  std::fill(row_count_.begin(), row_count_.end(), 0);  // particles larger than L emit nothing
  // One pass per sub-domain: each owned emitter's partners, appended to the sub-domain's
  // own buffer; then every row is copied to its place in the list.
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
  for (int k = 0; k < domains; ++k) {
    std::vector<std::int32_t>& found = found_[static_cast<std::size_t>(k)];
    found.clear();
    const auto staged = d.members(k);
    for (const std::int32_t i : d.owned(k)) {
      run_start_[i] = static_cast<std::int64_t>(found.size());
      visit_pairs(i, staged, g, periodic, [&found](std::int32_t j) { found.push_back(j); });
      row_count_[i] = static_cast<std::int64_t>(found.size()) - run_start_[i];
    }
  }
  exclusive_scan(row_count_, row_count_.size(), pairs.offset);
  grow_to(pairs.partner, pairs.count());
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
  for (int k = 0; k < domains; ++k) {
    const std::vector<std::int32_t>& found = found_[static_cast<std::size_t>(k)];
    for (const std::int32_t i : d.owned(k)) {
      const std::int64_t begin = pairs.offset[i], end = pairs.offset[i + 1];
      std::copy(found.begin() + run_start_[i], found.begin() + run_start_[i] + (end - begin),
                pairs.partner.begin() + begin);
      sort_row(pairs.partner.data(), begin, end);  // walls come after the staged partners
    }
  }
}

template class DecomposedPairs<float>;
template class DecomposedPairs<double>;

}  // namespace tridem
