#pragma once
// The CPU solvers: the serial reference and its OpenMP twin are one code, run with
// `parallel` off or on. Every stage writes only memory it owns (a pair's slot, a
// particle's row), and every sum runs in a fixed order (pairs ascending), so the OpenMP
// solver reproduces the serial one bit for bit; that is what the parity tests check.
#include "backends/cpu/partner_record.hpp"
#include "backends/cpu/thread_choice.hpp"
#include "broadphase/candidate_pairs.hpp"
#include "broadphase/default_init_allocator.hpp"
#include "broadphase/single_domain.hpp"
#include "core/bond_columns.hpp"
#include "core/ghost_overlap.hpp"
#include "core/particle_model.hpp"
#include "core/stage_pipeline.hpp"
#include "core/time_step.hpp"
#include "decomposition/decomposed_pairs.hpp"
#include "physics/bond_step.hpp"
#include "physics/contact_force.hpp"
#include "physics/integrate.hpp"
#include "physics/motion_program.hpp"
#include "physics/periodic_frame.hpp"
#include "physics/rigid_body.hpp"
#include "tridem/body_fields.hpp"
#include "tridem/particle_fields.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace tridem {

template <class Real>
class CpuSolver final : public Solver {
 public:
  CpuSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
            const SolverConfig& config, bool parallel);

  void advance(std::int64_t steps) override;
  void snapshot(Snapshot& out, bool with_contacts) const override;
  std::unique_ptr<StateCopy> make_state_copy() const override;  // cpu_state_copy.cpp
  void save_state(SolverState& out) const override;     // cpu_solver_state.cpp
  void load_state(const SolverState& in) override;
  EnergyBudget energy() const override;
  std::int64_t step() const override { return step_; }
  double time() const override { return time_; }
  double dt() const override { return dt_; }
  std::size_t size() const override { return n_; }
  std::string description() const override;
  std::string statistics() const override;
  StageTimes stage_times() const override;
  void set_stage_timing(bool on) override { stopwatch_.on = on; }

  /// The stages in the order advance() runs them (core/stage_pipeline.hpp): each its own
  /// loops over particles or pairs, none fused; all of them on one OpenMP team per step
  /// (run_step_on_team).
  static constexpr std::array<Stage, kStageCount> kPipeline = {
      Stage::Geometry, Stage::PairList, Stage::PairForces,
      Stage::Gather,   Stage::Check,    Stage::Integrate};
  void run_stage(Stage stage);

  /// The columns of a per-particle field, by its tag (generic code: snapshots, states).
  TRIDEM_PARTICLE_FIELDS(TRIDEM_MEMBER_COLUMN_ACCESSOR)
  /// The per-body and per-member columns (tridem/body_fields.hpp); empty without bodies.
  TRIDEM_BODY_FIELDS(TRIDEM_BODY_MEMBER_COLUMN_ACCESSOR)
  TRIDEM_MEMBER_FIELDS(TRIDEM_BODY_MEMBER_COLUMN_ACCESSOR)
  std::size_t bodies() const { return n_bodies_; }
  std::size_t bonds() const { return bonds_.size(); }
  const HostBondColumns<Real>& bond_columns() const { return bonds_; }

  /// The pairs of the last completed step and their forces (between steps): MPI ranks
  /// (src/mpi/) sum the walls' loads, the elastic energy and the contacts across ranks
  /// from them, in the order one solver would.
  const PairList& last_pairs() const { return old_pairs_; }
  const std::vector<physics::PairForce<Real>>& last_forces() const { return result_; }
  /// The pairs of the step in progress, from its check hook on (last_forces() then holds
  /// their forces): MPI ranks sum a servo wall's load across ranks there.
  const PairList& step_pairs() const { return pairs_; }
  /// Called after every step's Check, before anything is written; it may throw RunError
  /// (MPI ranks agree there whether every rank's step is good, so that a blow-up on one
  /// leaves every rank at the last good state).
  void set_check_hook(std::function<void()> hook) { check_hook_ = std::move(hook); }

  /// MPI ranks (mpi/cpu_rank, docs/scaling.md "Overlap"): whether this solver can take its
  /// ghosts' states in the middle of a step, after the pairs of its own particles: the grid
  /// method, without a periodic cell, with a skin (the list is kept between steps).
  bool can_take_ghosts_mid_step() const {
    return method_ == Method::Grid && !periodic_ && margin_ > Real(0);
  }
  /// Turns that on: `received` flags (one a particle) the particles whose State arrives from
  /// other ranks; `take()` writes it, once a step, before anything of this step reads it
  /// (on the team's first thread); `poll()` is called now and then meanwhile (the first
  /// thread), to let the transfer progress.
  void set_ghost_hooks(std::vector<std::uint8_t> received, std::function<void()> take,
                       std::function<void()> poll);
  /// How many times the kept list (grid, no periodic cell, a skin) was built from build
  /// boxes: the other steps kept the last step's list.
  std::int64_t list_builds() const { return list_builds_; }
  /// What the split step did (set_ghost_hooks; zeros without).
  const GhostOverlapCounts& overlap_counts() const { return overlap_counts_; }

 private:
  void run_step_on_team();
  // The stages' functions are team code (core/omp_team.hpp): every thread of the step's
  // team calls them, their loops are worksharing loops, their serial parts team_single.
  void find_pairs();
  /// The reverse index and the pairs' slots for the list just built.
  void finish_pair_list();
  void compute_pair_forces();
  // Which particles (geometry) or slots (pair forces) a pass of the split step covers:
  // all, those of no received particle (Own), or those of some received one (Ghosts).
  enum class Part { All, Own, Ghosts };
  void update_geometry(Part part);
  void compute_pair_slots(Part part);
  void report_too_deep();
  void kept_pair_list();
  void keep_last_list();
  // The split step's stages (set_ghost_hooks).
  void split_pair_list();
  void split_pair_forces();
  void take_ghosts();
  void build_grown_list();
  void test_build_boxes(Part part);
  [[noreturn]] void report_penetration(std::int32_t emitter) const;
  void accumulate();
  void check_runaway() const;
  template <class IsFree, class Advanced, class HalfSize>
  std::int64_t first_runaway(std::int64_t n, IsFree is_free, Advanced advanced,
                             HalfSize half_size) const;
  void integrate();
  void add_step_energy(std::size_t i, const physics::Pose<double>& before,
                       const physics::Pose<double>& after, bool free);
  // Bodies of several members (n_bodies_ > 0): the gather, check and integration run per
  // body; the triangles follow their bodies.
  void gather_bodies();
  void check_body_runaway() const;
  void integrate_bodies();
  void place_members();
  // Cohesive bonds (bonds() > 0; docs/fracture.md): their forces computed with the pair
  // forces, summed into each particle's load after its pairs (its bonds in ascending
  // order), their damage written with the step (Integrate), so that a blow-up leaves the
  // last good damage in place.
  void compute_bond_forces();
  void add_bond_loads();
  void commit_bonds();
  physics::Pose<double> body_pose(std::size_t b) const {
    return {{body_x_[b], body_y_[b]}, body_theta_[b], {body_vx_[b], body_vy_[b]}, body_w_[b]};
  }
  physics::Pose<double> advanced_body_pose(std::size_t b) const;

  /// Body i as pair_force sees it, in the frame whose origin is at `origin`.
  physics::Body<Real> body(std::int32_t i, Vec2d origin) const;
  /// Its nearest periodic image as pair_force sees it (periodic boundaries).
  physics::Body<Real> image_body(std::int32_t i, Vec2d origin,
                                 const physics::PeriodicImage& im) const;
  /// A free particle (body) of inverse mass `inv_mass` put back into the cell, and what
  /// that gave it booked as the boundary's work on particle `booked`.
  void wrap(const physics::PeriodicFrame& frame, physics::Pose<double>& p, double inv_mass,
            std::size_t booked);
  /// The periodic cell at time t (periodic_ only).
  physics::PeriodicFrame frame_at(double t) const;
  physics::Pose<double> pose(std::size_t i) const {
    return {{x_[i], y_[i]}, theta_[i], {vx_[i], vy_[i]}, w_[i]};
  }
  physics::Pose<double> advanced_pose(std::size_t i) const;

  std::size_t n_;
  bool openmp_;    ///< the openmp backend (else the serial reference)
  bool parallel_;  ///< this step runs on the threads (choice_ decides, step by step)
  ThreadChoice choice_;
  int threads_;  ///< OpenMP threads while advancing; 0 = the runtime's default
  Method method_;
  // Mixed precision (docs/model.md, "Precision"): the state and its integration are
  // double in every precision; Real is what pairs and their forces are computed in.
  double dt_;
  Vec2d gravity_;
  double local_damping_;
  Real penetration_limit_;  ///< largest PairForce::depth accepted
  TimeStep limit_;          ///< dt_crit and what sets it, for the blow-up messages
  std::int64_t step_ = 0;
  double time_ = 0;

  // The per-particle fields (tridem/particle_fields.hpp) as member_ vectors: offset_x_,
  // x_, fx_, energy_, rel_x_, lo_x_, ...
  TRIDEM_PARTICLE_FIELDS(TRIDEM_DECLARE_MEMBER_COLUMNS)
  std::size_t n_bodies_ = 0;  ///< bodies, when some has several members; else 0
  TRIDEM_BODY_FIELDS(TRIDEM_DECLARE_MEMBER_COLUMNS)
  TRIDEM_MEMBER_FIELDS(TRIDEM_DECLARE_MEMBER_COLUMNS)
  // Bonds (empty without; core/bond_columns.hpp): the model in Real, each particle's list,
  // the damage of each bond's points and whether it broke, its dissipated energy (J/m,
  // cumulative), and this step's forces; bond_view_ points into them (the shared rules of
  // physics/bond_step.hpp read it).
  HostBondColumns<Real> bonds_;
  physics::BondArrays<Real> bond_view_{};
  std::vector<physics::LawParameters<Real>> laws_;
  int n_materials_;
  bool walls_move_ = false;  ///< some fixed or prescribed particle has a velocity
  // The walls' motion programs (physics/motion_program.hpp), as the model resolved them.
  std::vector<MotionProgram> programs_;
  ShownIds shown_ids_;  ///< ParticleModel::shown_ids: the ids the messages name
  std::vector<ProgramKnot> program_knots_;
  // The step's target force of each program, when some servo follows a length
  // (length_between; empty without): filled by update_servo_targets in the Gather stage.
  std::vector<double> servo_targets_;
  physics::ProgramTable program_table() const {
    return {programs_.data(), program_knots_.data(),
            servo_targets_.empty() ? nullptr : servo_targets_.data()};
  }
  void write_program_velocities();
  void update_servo_targets();
  // Pairs of this step and the last, with their contact history. The method picks the
  // finder: the cell grid and all-pairs list box-overlapping pairs, single-domain only
  // those that pass its contact test.
  CandidatePairs<Real> finder_;
  ContactFilter filter_;
  SingleDomainPairs<Real> single_domain_;
  std::optional<DecomposedPairs<Real>> decomposed_;  ///< method = decomposition
  PairList pairs_, old_pairs_;
  std::vector<physics::PairSlip<Real>> slip_, old_slip_;
  std::vector<physics::PairForce<Real>> result_;
  /// Each particle's fields as its pairs read them, written by the Geometry stage before
  /// any pair reads them (so not zeroed first: its pages are touched by the threads).
  UnfilledVector<PartnerRecord<Real>> partner_;
  ReverseIndex reverse_;
  StageStopwatch stopwatch_;
  // The lowest index the team's threads found too deep (a pair's emitter) or running away
  // (a particle or body) in this step: folded by the threads, kNoIndex when none.
  static constexpr std::int64_t kNoIndex = std::numeric_limits<std::int64_t>::max();
  std::int64_t too_deep_ = kNoIndex;
  /// Whether this step's pairs compute their stored energy: only the last step of an
  /// advance() does (energy(), contacts and snapshots read that step's results), as the
  /// GPU writes its pair details only then.
  bool pair_energy_ = true;
  mutable std::int64_t first_runaway_ = kNoIndex;
  std::function<void()> check_hook_;
  // Periodic boundaries (physics/periodic_frame.hpp): pairs see their partners' nearest
  // images, free particles (bodies) are put back into the cell as they step.
  bool periodic_ = false;
  PeriodicCell cell_;
  // Lees-Edwards only (empty otherwise): each emitter row's image_power of this step, booked
  // as wall work when the step is written (the GPU's StepParams::image_power).
  std::vector<double> image_power_;
  // Kept lists (keeps_lists_: the grid, no periodic cell, a skin): the list is built from
  // the boxes grown by margin_ on each side (the build boxes), and kept while every box is
  // inside its build box; so, in the split step of MPI ranks (set_ghost_hooks), a step's own
  // pairs need no ghost. A kept list holds pairs whose boxes no longer overlap: those get
  // the exact zeros of an unlisted pair (the current boxes are tested in
  // compute_pair_slots), so that the results are those of a list built every step.
  Real margin_ = 0;  ///< the skin (scene.simulation.skin times the grid's cell)
  bool keeps_lists_ = false;
  std::int64_t list_builds_ = 0;  ///< lists built from build boxes
  std::vector<std::uint8_t> received_;
  std::function<void()> take_ghosts_, poll_;
  std::vector<Real> build_lo_x_, build_lo_y_, build_hi_x_, build_hi_y_;
  bool list_kept_ = false;  ///< the last step completed on a list built with build boxes
  bool may_keep_ = false;   ///< this step started with such a list
  bool same_list_ = false;  ///< this step's list is the last step's (history by slot)
  bool ghosts_taken_ = false;
  int left_box_ = 0;       ///< some box left its build box (folded by the team)
  int ghost_contact_ = 0;  ///< some pair on a ghost touched (folded by the team)
  GhostOverlapCounts overlap_counts_;
};

}  // namespace tridem
