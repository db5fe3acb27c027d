#pragma once
// The pair list of the CUDA solver and how it is rebuilt: its pair slots sized by the first
// list's count and a fifth more (core/memory_estimate.hpp, pair_slots_for), grown the same
// way only if a run packs denser. The pairs are found by the cell grid or all-pairs
// (broad_phase_kernels.cuh) or by the paper's single-domain kernel
// (single_domain_kernels.cuh); the rows, contact history and reverse index that follow are
// one code for all. Between grid builds the list stays, and with it every pair's slot and
// contact history: a pair is in the list as long as the boxes grown by the skin overlap.
// A single-domain list holds only the pairs that passed the contact test at the positions
// of its build, so it serves one step.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/grid_types.cuh"
#include "backends/cuda/row_history.cuh"
#include "backends/cuda/single_domain_kernels.cuh"
#include "backends/cuda/slot_phases.cuh"
#include "broadphase/periodic_grid.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem::cuda {

template <class Real>
struct PeriodicFinder;

template <class Real>
class PairListBuilder {
 public:
  /// `small` per particle; `cell` the width of the widest build box; `filter` the
  /// contact test of method single-domain.
  PairListBuilder(const std::vector<std::uint8_t>& small, Method method, Real cell,
                  ContactFilter filter, std::size_t pair_capacity, cudaStream_t stream);

  /// A new list for the current boxes, grown by `margin` (grid and all-pairs), or of the
  /// pairs passing the contact test now (single-domain); carries the contact history of
  /// the old list over. Synchronises once, to learn the number of pairs.
  /// In a periodic cell (set_periodic), pairs are also found across its boundaries, each
  /// box tested against its partner's nearest image in `frame`.
  void rebuild(const ParticleArrays<Real>& p, Real margin,
               const physics::PeriodicFrame& frame = physics::PeriodicFrame{});
  /// A periodic cell: grid and all-pairs find pairs through its boundaries; an image across
  /// a Lees-Edwards boundary is listed while it is within `sheared_slack` of the box it
  /// must touch (the solver rebuilds before the images slide farther).
  void set_periodic(double sheared_slack);
  /// A list found by another method's kernels (the decomposition's sub-domains), through
  /// the same rows, history and reverse index: count(row_count) writes the length of every
  /// particle's row into n counts (zero where it emits nothing), fill(history()) writes the
  /// rows, sorted, and calls carry_history. Synchronises once, to learn the number of pairs.
  template <class Count, class Fill>
  void rebuild_with(Count&& count, Fill&& fill) {
    count(row_count_.data());
    size_rows();
    fill(history());
    index_rows();
    ++builds_;
  }
  /// Whether a list serves only the step it was built for.
  bool single_step() const { return method_ == Method::SingleDomain; }

  /// Replaces the list (and its history) by one given on the host: rows by emitter,
  /// partners ascending. The next rebuild carries its slips over.
  void load(const std::vector<int>& offset, const std::vector<int>& partner,
            const std::vector<physics::PairSlip<Real>>& slip);

  PairArrays<Real> arrays() const;
  int count() const { return count_; }
  std::size_t capacity() const { return partner_.size(); }
  std::int64_t builds() const { return builds_; }

  /// The list of the last step on the host (for contact output and checkpoints). The
  /// results' details are those of the last step that wrote them (StepParams::details).
  void download(std::vector<int>& offset, std::vector<int>& partner,
                std::vector<physics::PairSlip<Real>>* slip,
                std::vector<physics::PairForce<Real>>* result) const;
  /// Zeroes the details, so that a deep pair reported once is not found again in a slot
  /// that a later step leaves unwritten.
  void clear_details() const;

 private:
  void reserve_pairs(std::size_t pairs);
  /// Throws RunError, naming the pairs and the memory, when growing the slots to `pairs`
  /// needs more GPU memory than is free.
  void refuse_unless_pairs_fit(std::size_t pairs) const;
  /// CUB's scratch: temp_ for the cells' sort and the scans; returns the bytes the reverse
  /// index's sort of `pairs` slots needs (in phases_).
  std::size_t size_temp_storage(std::size_t pairs);
  CandidateSearch<Real> search(const ParticleArrays<Real>& p) const;
  SingleDomainSearch<Real> single_domain_search(const ParticleArrays<Real>& p) const;
  /// Single-domain: the paper's count and fill kernels, plain or periodic.
  template <bool kPeriodic>
  void single_domain_rows(const SingleDomainSearch<Real>& c);
  /// Grid: the small particles sorted by their cell, plain or periodic.
  void bin(const CandidateSearch<Real>& c);
  void bin_periodic(const PeriodicFinder<Real>& find);
  void sort_by_cell();
  /// Grid or all-pairs: the rows counted, sized and filled by a finder.
  template <class Finder>
  void fill_rows(const Finder& find);
  /// From row_count_: the offsets of the new rows (the old list kept in phases_ for the
  /// history), the number of pairs (one synchronisation) and room for them.
  void size_rows();
  RowHistory<Real> history() const;
  /// The reverse index of the new rows; then the details' room is cleared of the build's
  /// scratch.
  void index_rows();

  int n_;
  Method method_;
  Real cell_;
  ContactFilter filter_;
  cudaStream_t stream_;
  unsigned int beyond_;  ///< key of particles outside the grid; > every cell index
  int cell_bits_, particle_bits_;
  int count_ = 0;
  int old_count_ = 0;  ///< the old list's pairs, while size_rows holds them in phases_
  std::int64_t builds_ = 0;
  int n_large_ = 0;
  bool periodic_ = false;
  double sheared_slack_ = 0;
  DeviceBuffer<PeriodicGrid> periodic_grid_;  ///< the periodic grid of the last build

  DeviceBuffer<std::uint8_t> small_;
  DeviceBuffer<int> large_;
  DeviceBuffer<CornerBounds<Real>> bounds_;
  DeviceBuffer<GridParams<Real>> grid_;
  DeviceBuffer<unsigned int> cell_of_, sorted_cell_;
  DeviceBuffer<int> index_, sorted_;
  DeviceBuffer<int> cell_start_, cell_end_;
  DeviceBuffer<int> row_count_;
  // The rows' offsets and the old ones (for the history), swapped at each build.
  DeviceBuffer<int> offset_, old_offset_;
  DeviceBuffer<int> partner_;
  DeviceBuffer<physics::PairSlip<Real>> slip_;
  DeviceBuffer<int> emitter_;
  DeviceBuffer<physics::PairLoad<Real>> load_;
  // Reverse index: slots sorted by partner.
  DeviceBuffer<int> reverse_slot_, reverse_offset_;
  /// The old list, slot ids and reverse-index sort of a build; the details between builds.
  SlotPhases<Real> phases_;
  DeviceBuffer<std::uint8_t> temp_;  ///< CUB scratch of the per-particle sort and scans
  PinnedBuffer<int> total_;
};

}  // namespace tridem::cuda
