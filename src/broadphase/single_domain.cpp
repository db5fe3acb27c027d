#include "broadphase/single_domain.hpp"

#include <utility>

namespace tridem {

template <class Real>
SingleDomainPairs<Real>::SingleDomainPairs(const std::vector<double>& longest_edge,
                                           const std::vector<Motion>& motion,
                                           ContactFilter filter)
    : free_(motion.size()), filter_(filter), row_count_(motion.size()) {
  GridClasses classes = classify_for_grid(longest_edge, motion);
  small_ = std::move(classes.small);
  for (std::size_t i = 0; i < motion.size(); ++i) {
    free_[i] = motion[i] == Motion::Free;
    if (!small_[i]) large_.push_back(static_cast<std::int32_t>(i));
  }
}

template <class Real>
void SingleDomainPairs<Real>::find(const TriangleArrays<Real>& g, bool parallel, PairList& pairs,
                                   const physics::PeriodicFrame* periodic) {
  const auto n = static_cast<std::int32_t>(free_.size());
  fill_rows(free_.size(), parallel, row_count_, pairs, [&](std::int32_t i, auto&& emit) {
    if (!small_[i]) return;  // large particles are reached from the small ones
    const EmitterTest<Real> passes(g, i, small_.data(), free_.data(), filter_, periodic);
    auto consider = [&](std::int32_t j) {
      if (passes(j)) emit(j);
    };
    // Partners ascending: the walls below i, then every particle above it.
    for (const std::int32_t j : large_) {
      if (j > i) break;
      consider(j);
    }
    for (std::int32_t j = i + 1; j < n; ++j) consider(j);
  });
}

template class SingleDomainPairs<float>;
template class SingleDomainPairs<double>;

}  // namespace tridem
