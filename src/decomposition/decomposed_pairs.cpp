#include "decomposition/decomposed_pairs.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "physics/geometry.hpp"

#include <algorithm>

namespace tridem {

template <class Real>
DecomposedPairs<Real>::DecomposedPairs(const SimulationSettings& settings,
                                       const std::vector<double>& longest_edge,
                                       const std::vector<Motion>& motion)
    : test_(settings.contact_test),
      prefilter_(settings.bbox_prefilter),
      free_(motion.size()),
      decomposition_(settings.decomposition, classify_for_grid(longest_edge, motion).cell,
                     classify_for_grid(longest_edge, motion).small),
      row_count_(motion.size()),
      run_start_(motion.size()) {
  for (std::size_t i = 0; i < motion.size(); ++i) free_[i] = motion[i] == Motion::Free;
}

template <class Real>
template <class Emit>
void DecomposedPairs<Real>::visit_pairs(std::int32_t i, std::span<const std::int32_t> staged,
                                        const DomainInput<Real>& in,
                                        const VertexArrays<Real>& v, Emit&& emit) const {
  auto triangle = [&v](std::int32_t p) {
    return physics::Triangle<Real>{
        {{v.x[0][p], v.y[0][p]}, {v.x[1][p], v.y[1][p]}, {v.x[2][p], v.y[2][p]}}};
  };
  auto box = [&in](std::int32_t p) {
    return physics::Aabb<Real>{{in.lo_x[p], in.lo_y[p]}, {in.hi_x[p], in.hi_y[p]}};
  };
  const physics::Triangle<Real> a = triangle(i);
  const physics::Aabb<Real> a_box = box(i);
  auto consider = [&](std::int32_t j) {
    if (!(free_[i] || free_[j])) return;
    if (prefilter_ && !physics::boxes_overlap(a_box, box(j))) return;
    const physics::Triangle<Real> b = triangle(j);
    const bool touching = test_ == ContactTest::Exact ? physics::triangles_overlap(a, b)
                                                      : physics::direct_area_overlap(a, b);
    if (touching) emit(j);
  };
  // Staged particles are ascending: those after i are its partners among the small ones.
  for (auto it = std::upper_bound(staged.begin(), staged.end(), i); it != staged.end(); ++it)
    consider(*it);
  for (const std::int32_t j : decomposition_.large()) consider(j);
}

template <class Real>
void DecomposedPairs<Real>::find(const DomainInput<Real>& in, const VertexArrays<Real>& v,
                                 bool parallel, PairList& pairs) {
  decomposition_.update(in);
  const Decomposition<Real>& d = decomposition_;
  const int domains = d.count();
  if (found_.size() < static_cast<std::size_t>(domains)) found_.resize(static_cast<std::size_t>(domains));
  std::fill(row_count_.begin(), row_count_.end(), 0);  // particles larger than L emit nothing
  // One pass per sub-domain: each owned emitter's partners, appended to the sub-domain's
  // own buffer.
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
  for (int k = 0; k < domains; ++k) {
    std::vector<std::int32_t>& found = found_[static_cast<std::size_t>(k)];
    found.clear();
    const auto staged = d.members(k);
    for (const std::int32_t i : d.owned(k)) {
      run_start_[i] = static_cast<std::int64_t>(found.size());
      visit_pairs(i, staged, in, v, [&found](std::int32_t j) { found.push_back(j); });
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
