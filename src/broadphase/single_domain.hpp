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

template <class Real>
class SingleDomainPairs {
 public:
  /// `longest_edge` and `motion` are per particle; they fix which particles emit.
  SingleDomainPairs(const std::vector<double>& longest_edge, const std::vector<Motion>& motion,
                    ContactFilter filter);

  /// Fills `pairs` with the pairs that pass the test. `parallel` runs it with OpenMP.
  void find(const TriangleArrays<Real>& geometry, bool parallel, PairList& pairs);

 private:
  std::vector<std::uint8_t> small_, free_;
  std::vector<std::int32_t> large_;  ///< ascending
  ContactFilter filter_;
  std::vector<std::int64_t> row_count_;
};

}  // namespace tridem
