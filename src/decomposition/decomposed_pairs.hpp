#pragma once
// The CPU decomposition method: pairs found inside each sub-domain among what it stages,
// with the paper's per-pair decision (contact_filter.hpp), written into the same pair list
// (rows by emitter, partners ascending) as the other methods. A sub-domain writes the rows
// of the emitters it owns and no others, so sub-domains run in parallel with nothing
// shared, and the list does not depend on the schedule: OpenMP gives the serial list.
#include "broadphase/contact_filter.hpp"
#include "broadphase/pair_list.hpp"
#include "broadphase/single_domain.hpp"
#include "decomposition/decomposition.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

template <class Real>
class DecomposedPairs {
 public:
  /// `longest_edge` and `motion` per particle, as for CandidatePairs.
  DecomposedPairs(const DecompositionSettings& settings, const std::vector<double>& longest_edge,
                  const std::vector<Motion>& motion, ContactFilter filter);

  /// Brings the decomposition up to date for centroids (x, y) and the geometry (migration,
  /// borders), then fills `pairs` with the pairs that pass the contact test. In a periodic
  /// cell (`periodic`, this step's frame) each partner is tested at its nearest image.
  void find(const double* x, const double* y, const TriangleArrays<Real>& geometry, bool parallel,
            PairList& pairs, const physics::PeriodicFrame* periodic = nullptr);

  const Decomposition<Real>& decomposition() const { return decomposition_; }

 private:
  template <class Emit>
  void visit_pairs(std::int32_t i, ParticleRange staged, const TriangleArrays<Real>& g,
                   const physics::PeriodicFrame* periodic, Emit&& emit) const;

  ContactFilter filter_;
  std::vector<std::uint8_t> small_, free_;
  Decomposition<Real> decomposition_;
  // Partners found by each sub-domain, in the order of its owned emitters, and where each
  // emitter's run starts in it. Kept at their high-water marks.
  std::vector<std::vector<std::int32_t>> found_;
  std::vector<std::int64_t> row_count_, run_start_;
};

}  // namespace tridem
