#pragma once
// Dynamic domain decomposition (Zhang, Quigley & Chan 2012, §5): the bookkeeping of which
// sub-domain owns each particle and which particles each sub-domain stages, kept up to date
// step after step.
//
// A particle is owned by the sub-domain whose cells hold its centroid (cells of size L,
// the grid cell). A sub-domain stages its owned particles and its overlap band: every
// other particle whose box reaches the hull of the owned boxes. The hull lies within L of
// the sub-domain's cells, so this band is the paper's band of width L, trimmed to the
// particles that can touch an owned one; and every pair with overlapping boxes has its
// emitter owned somewhere and its partner staged there, so detection inside the
// sub-domains finds each pair exactly once. Particles larger than L (walls) belong to no
// sub-domain: every sub-domain checks them, as the cell grid does.
//
// Borders are whole cell columns (and, in 2D, rows of fixed height, the paper's DLy). They
// are computed from the per-column counts as in the paper's Fig. 17 (a row is cut where
// one more column would put the sub-domain, band included, above the capacity), kept
// while particles migrate, and when a sub-domain overflows its border moves by one
// occupied cell column towards it, handing that column to the neighbour that can take
// it; when neither can, the row's borders are computed anew. A column that alone exceeds
// the capacity is an error that says what to change.
#include "decomposition/domain_map.hpp"
#include "decomposition/row_cut.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace tridem {

/// Centroids (double in every precision: docs/model.md, "Precision") and boxes of every
/// particle at the current step.
template <class Real>
struct DomainInput {
  const double *x, *y;
  const Real *lo_x, *lo_y, *hi_x, *hi_y;
};

/// The particles of one sub-domain, ascending (a span; this header is also compiled as
/// C++17 by nvcc).
struct ParticleRange {
  const std::int32_t* first;
  const std::int32_t* last;
  const std::int32_t* begin() const { return first; }
  const std::int32_t* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
};

/// What the decomposition did so far, for the solver's statistics.
struct DecompositionStats {
  std::int64_t updates = 0;       ///< steps the bookkeeping was brought up to date
  std::int64_t migrations = 0;    ///< particles that changed owner between two steps
  std::int64_t overflows = 0;     ///< times a sub-domain was found above capacity
  std::int64_t border_moves = 0;  ///< borders moved to relieve an overflow
  std::int64_t repartitions = 0;  ///< rows whose borders were computed anew (after the first)
  int max_members = 0;            ///< most particles staged by one sub-domain so far
};

/// One line for the run's summary: sub-domains, staging, migrations, border moves.
std::string decomposition_summary(const DecompositionStats& s, int sub_domains, int rows,
                                  int capacity);

template <class Real>
class Decomposition {
 public:
  /// `cell` is the grid cell L; `small` marks the particles the grid bins (the others are
  /// checked by every sub-domain).
  Decomposition(const DecompositionSettings& settings, double cell,
                std::vector<std::uint8_t> small);

  /// Assigns owners and overlap bands for the current step; the first call computes the
  /// borders, later ones move them when a sub-domain overflows. Throws RunError when some
  /// cell column cannot fit in one sub-domain.
  /// `parallel` runs it with OpenMP; the result is the same. In a periodic cell
  /// (`periodic`, the frame of this step) a sub-domain also stages the particles whose
  /// images across the boundaries reach its hull, so that every pair through a boundary
  /// has its partner staged with its emitter, at some image.
  void update(const DomainInput<Real>& in, bool parallel = false,
              const physics::PeriodicFrame* periodic = nullptr);

  int count() const { return static_cast<int>(col_begin_.size()); }
  int rows() const { return static_cast<int>(row_begin_.size()); }
  DomainMap map() const;

  /// Sub-domain owning particle p, or -1 for particles larger than L.
  int owner(std::size_t p) const { return owner_[p]; }
  /// Particles owned by / staged by sub-domain k, ascending.
  ParticleRange owned(int k) const;
  ParticleRange members(int k) const;
  /// The same for every sub-domain at once, in compressed rows (count() + 1 offsets).
  const std::vector<std::int32_t>& member_offset() const { return member_offset_; }
  const std::vector<std::int32_t>& member_list() const { return members_; }
  const std::vector<std::int32_t>& owned_offset() const { return owned_offset_; }
  const std::vector<std::int32_t>& owned_list() const { return owned_; }
  const std::vector<std::int32_t>& owners() const { return owner_; }
  const std::vector<std::int32_t>& large() const { return large_; }
  int capacity() const { return settings_.capacity; }
  const DecompositionStats& stats() const { return stats_; }
  /// One line for the run's summary: sub-domains, staging, migrations, border moves.
  std::string summary() const;

 private:
  void compute_cells(const DomainInput<Real>& in);
  void initial_partition(const DomainInput<Real>& in);
  void assign(const DomainInput<Real>& in);
  int first_overflowing() const;
  bool move_border(int k, const DomainInput<Real>& in);
  void partition_row(int row, const DomainInput<Real>& in);
  void index_rows();
  /// Calls visit(q) for every sub-domain owning a cell within kReachCells of k's cells:
  /// the only ones whose particles can reach k's hull.
  template <class Visit>
  void visit_neighbours(int k, Visit&& visit) const;
  /// Appends to `staged` the particles owned anywhere whose boxes, moved by one of the
  /// periodic cell's image translations, reach `h` (the frame's images that can: those
  /// that bring some owned box near it).
  void stage_images(const Hull<Real>& h, std::vector<std::int32_t>& staged) const;
  /// In a periodic cell, the boxes of the particles whose images reach the y-extent of a
  /// row, moved to those images, join the row's band (partition_row).
  void add_image_bands(Real y_lo, Real y_hi, const DomainInput<Real>& in,
                       BandCounter<Real>& band) const;
  int row_of_domain(int k) const;
  int staged(int k) const { return member_offset_[k + 1] - member_offset_[k]; }

  DecompositionSettings settings_;
  double cell_;
  std::size_t n_;
  std::vector<std::uint8_t> small_;
  std::vector<std::int32_t> large_;
  bool started_ = false;
  bool parallel_ = false;
  bool periodic_ = false;
  physics::PeriodicFrame frame_{};  ///< this update's, when periodic_
  Hull<double> extent_{};           ///< of every small particle's box, when periodic_
  double origin_x_ = 0, origin_y_ = 0;

  // Borders (see DomainMap).
  std::vector<std::int64_t> row_begin_, col_begin_;
  std::vector<int> row_first_;

  // Per particle, this step.
  std::vector<std::int64_t> cell_row_, cell_col_;
  std::vector<std::int32_t> owner_, last_owner_;
  // Per sub-domain, this step.
  std::vector<std::int32_t> owned_offset_, owned_, member_offset_, members_;
  std::vector<Hull<Real>> hull_;
  std::vector<Hull<Real>> owned_box_;  ///< box of each owned_ entry, in that order
  // Scratch, kept to its high-water mark.
  std::vector<std::int32_t> cursor_, row_particles_;
  std::vector<std::vector<std::int32_t>> staged_;       ///< members, per sub-domain
  std::vector<std::int32_t> by_row_, by_row_offset_;    ///< particles by row (cutting)

  DecompositionStats stats_;
};

}  // namespace tridem
