#pragma once
// The CPU decomposition method: pairs found inside each sub-domain among what it stages,
// written into the same pair list (rows by emitter, partners ascending) as the cell grid.
// A sub-domain writes the rows of the emitters it owns and no others, so sub-domains run
// in parallel with nothing shared, and the list does not depend on the schedule: OpenMP
// gives the serial list exactly.
#include "broadphase/pair_list.hpp"
#include "decomposition/decomposition.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

/// Vertices of every particle at the current step.
template <class Real>
struct VertexArrays {
  const Real* x[3];
  const Real* y[3];
};

template <class Real>
class DecomposedPairs {
 public:
  /// `longest_edge` and `motion` per particle, as for CandidatePairs; the settings give
  /// the decomposition, the contact test and the pre-filter.
  DecomposedPairs(const SimulationSettings& settings, const std::vector<double>& longest_edge,
                  const std::vector<Motion>& motion);

  /// Brings the decomposition up to date (migration, borders) and fills `pairs` with the
  /// pairs that pass the contact test.
  void find(const DomainInput<Real>& in, const VertexArrays<Real>& vertices, bool parallel,
            PairList& pairs);

  const Decomposition<Real>& decomposition() const { return decomposition_; }

 private:
  template <class Emit>
  void visit_pairs(std::int32_t i, std::span<const std::int32_t> staged,
                   const DomainInput<Real>& in, const VertexArrays<Real>& v, Emit&& emit) const;

  ContactTest test_;
  bool prefilter_;
  std::vector<std::uint8_t> free_;
  Decomposition<Real> decomposition_;
  // Partners found by each sub-domain, in the order of its owned emitters; where each
  // emitter's run starts in it. Kept at their high-water marks.
  std::vector<std::vector<std::int32_t>> found_;
  std::vector<std::int64_t> row_count_, run_start_;
};

}  // namespace tridem
