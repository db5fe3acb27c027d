#pragma once
// The paper's single-domain contact detection (its single-core baseline, §4): every pair
// is tested, with the bounding-box pre-filter if asked, then the contact test; only the
// pairs that pass go into the pair list, in rows by emitter (contact_filter.hpp's rule,
// the grid's), partners ascending. O(n²) work per step, by design: it is the reference the
// paper's GPU kernel and sub-domains are measured against.
#include "broadphase/candidate_pairs.hpp"
#include "broadphase/contact_filter.hpp"
#include "broadphase/pair_list.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

/// Whether emitter i lists the pair {i, j}: the emitter rule, then the contact test. One
/// per emitter, built once with i's triangle and box (single-domain and decomposition), in
/// the frame of i's centroid, as the pair's force is computed.
template <class Real>
class EmitterTest {
 public:
  /// With `periodic`, j is tested at its nearest image (passes_periodic_contact_test).
  EmitterTest(const TriangleArrays<Real>& g, std::int32_t i, const std::uint8_t* small,
              const std::uint8_t* free, ContactFilter filter,
              const physics::PeriodicFrame* periodic = nullptr)
      : g_(g),
        i_(i),
        origin_(g.centroid(i)),
        a_(g.triangle(i, origin_)),
        box_a_(g.box(i)),
        small_(small),
        free_(free),
        filter_(filter),
        periodic_(periodic) {}

  bool operator()(std::int32_t j) const {
    if (!emits_pair(i_, j, small_[i_] != 0, small_[j] != 0, free_[i_] != 0, free_[j] != 0))
      return false;
    if (periodic_)
      return passes_periodic_contact_test(*periodic_, origin_, a_, box_a_, g_, j, filter_);
    return passes_contact_test(a_, box_a_, g_.triangle(j, origin_), g_.box(j), filter_);
  }

 private:
  const TriangleArrays<Real>& g_;
  std::int32_t i_;
  Vec2d origin_;
  physics::Triangle<Real> a_;
  physics::Aabb<Real> box_a_;
  const std::uint8_t* small_;
  const std::uint8_t* free_;
  ContactFilter filter_;
  const physics::PeriodicFrame* periodic_;
};

template <class Real>
class SingleDomainPairs {
 public:
  /// `longest_edge` and `motion` are per particle; they fix which particles emit.
  SingleDomainPairs(const std::vector<double>& longest_edge, const std::vector<Motion>& motion,
                    ContactFilter filter);

  /// Fills `pairs` with the pairs that pass the test. `parallel` runs it with OpenMP.
  /// With `periodic`, each partner is tested at its nearest image in that cell.
  void find(const TriangleArrays<Real>& geometry, bool parallel, PairList& pairs,
            const physics::PeriodicFrame* periodic = nullptr);

 private:
  std::vector<std::uint8_t> small_, free_;
  std::vector<std::int32_t> large_;  ///< ascending
  ContactFilter filter_;
  std::vector<std::int64_t> row_count_;
};

}  // namespace tridem
