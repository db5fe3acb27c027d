#pragma once
// The CUDA solver: the whole time loop on one GPU with the single-source physics. The
// state stays on the GPU; only snapshots (output steps) copy it back. One step is the
// CPU solver's stages (kPipeline) with the same sums in the same order, so that both
// agree to rounding and two runs of one scene agree bit for bit.
#include "backends/cuda/body_buffers.cuh"
#include "backends/cuda/bond_buffers.cuh"
#include "backends/cuda/decomposed_rows.cuh"
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/pair_list_builder.cuh"
#include "backends/cuda/particle_buffers.cuh"
#include "backends/cuda/stage_events.cuh"
#include "backends/cuda/touching_pairs.cuh"
#include "core/ghost_overlap.hpp"
#include "core/particle_model.hpp"
#include "core/stage_pipeline.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tridem::cuda {

template <class Real>
class CudaStateCopy;  // live_state_copy.cu
template <class Real>
class CudaContactCopy;  // contact_copy.cu

template <class Real>
class CudaSolver final : public Solver {
 public:
  CudaSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
             const SolverConfig& config);
  ~CudaSolver() override;

  void advance(std::int64_t steps) override;
  void snapshot(Snapshot& out, bool with_contacts) const override;
  std::unique_ptr<StateCopy> make_state_copy() const override;  // live_state_copy.cu
  std::unique_ptr<ContactCopy> make_contact_copy() const override;  // contact_copy.cu
  std::int64_t step() const override { return step_; }
  double time() const override { return time_; }
  double dt() const override { return params_.dt; }
  std::size_t size() const override { return n_; }
  std::string description() const override;
  std::string statistics() const override;
  void save_state(SolverState& out) const override;  // cuda_solver_state.cu
  void load_state(const SolverState& in) override;
  EnergyBudget energy() const override;
  StageTimes stage_times() const override;
  void set_stage_timing(bool on) override { events_->on = on; }

  /// The stages in the order advance() runs them (core/stage_pipeline.hpp), with the
  /// fusions of its kernels:
  ///   PairList    [pair-list build, only when some box has left its build box; every
  ///               step for single-domain and decomposition], carrying contact history
  ///   PairForces  thread per pair; flags the lowest emitter of a too-deep pair
  ///   Gather      thread per particle, fused with Check's runaway test of each particle
  ///   Integrate   thread per particle, fused with the Geometry stage of the next step
  ///               (vertices, boxes, the rebuild flag), and with the step's energy
  ///   Check       the 12-byte status read back, the one synchronisation of a step, and
  ///               the blow-up reports
  static constexpr std::array<Stage, 5> kPipeline = {Stage::PairList, Stage::PairForces,
                                                     Stage::Gather, Stage::Integrate,
                                                     Stage::Check};
  void run_stage(Stage stage);

  // MPI ranks (backends/cuda/cuda_rank.cu, src/mpi/), never the solver alone. With a check
  // hook, advance() runs kRankPipeline: Check before Integrate, so that the ranks agree
  // every rank's step is good before any writes it (the hook may throw RunError); the
  // rebuild test is then read by state_written(), once the ghosts have their new states.
  static constexpr std::array<Stage, 5> kRankPipeline = {
      Stage::PairList, Stage::PairForces, Stage::Gather, Stage::Check, Stage::Integrate};
  void set_check_hook(std::function<void()> hook) { check_hook_ = std::move(hook); }
  ParticleArrays<Real> device_arrays() const { return arrays(); }
  /// The bodies of several members (n 0 without: the arrays then unallocated).
  BodyArrays device_body_arrays() const { return body_arrays(); }
  cudaStream_t stream() const { return stream_; }
  /// After kernels on stream() wrote some particles' State (a rank's ghosts): the geometry
  /// of the current state, and whether the pair list must be rebuilt (synchronises).
  void state_written();
  /// The last step's pair list and results, on the host; false (and nothing) before the
  /// first step and after load_state.
  bool last_pairs(std::vector<int>& offset, std::vector<int>& partner,
                  std::vector<physics::PairForce<Real>>& result) const;
  /// Each row's elastic energy as energy() adds them; empty when last_pairs has none.
  void row_elastic(std::vector<double>& rows) const;
  /// Each bond's elastic energy at the last step (0 before the first and after
  /// load_state, as energy() counts it) and the energy it has released, as energy() adds
  /// them (empty without bonds).
  void bond_terms(std::vector<double>& elastic, std::vector<double>& released) const;
  /// The pair list of the step in progress, its loads computed from the PairForces stage
  /// on (a check hook reads a servo wall's pairs there).
  PairArrays<Real> step_pair_arrays() const { return step_pairs_; }
  /// The split step (docs/scaling.md, "Overlap"): whether this solver can take its ghosts'
  /// states in the middle of a step, after the pairs of its own particles: the grid's kept
  /// list (not single-domain or decomposition), no periodic cell, a skin.
  bool can_take_ghosts_mid_step() const;
  /// Turns it on: `received` flags (one a particle) the particles whose State arrives from
  /// other ranks; `take()` completes the exchange and writes them (then state_written()),
  /// once a step, before anything of the step reads them. The host waits in it while the
  /// GPU computes the own particles' pairs.
  void set_ghost_hooks(const std::vector<std::uint8_t>& received, std::function<void()> take);
  /// What the split step did (set_ghost_hooks; zeros without).
  const GhostOverlapCounts& overlap_counts() const { return overlap_counts_; }

 private:
  friend class CudaStateCopy<Real>;  ///< the live view's copy reads the buffers and stream
  friend class CudaContactCopy<Real>;  ///< and the frames' contact copy the pairs
  ParticleArrays<Real> arrays() const { return d_.view(static_cast<int>(n_)); }
  BodyArrays body_arrays() const { return bodies_.view(static_cast<int>(n_bodies_)); }
  physics::BondArrays<Real> bond_arrays() const { return bonds_.view(); }
  /// The pair forces of this step, with the filters the scene needs (bodies, bonds).
  void launch_pair_forces(const ParticleArrays<Real>& p, StepStatus* status);
  template <bool kDetails, bool kPeriodic>
  void launch_pair_forces_with(const ParticleArrays<Real>& p, StepStatus* status);
  /// Lees-Edwards: whether the images have slid farther than the build's slack since it.
  bool images_slid() const;
  /// The list built from the current boxes grown by the skin, history carried over.
  void rebuild_list(const ParticleArrays<Real>& p);
  // The split step's stages (set_ghost_hooks): the list kept unless some box left its build
  // box (then the ghosts are taken first); the own pairs, the ghosts, then theirs.
  void split_pair_list(const ParticleArrays<Real>& p);
  void split_pair_forces(const ParticleArrays<Real>& p, StepStatus* status);
  void take_ghosts();
  /// The geometry of the current state (and a rebuild); with `place`, the members placed
  /// on their bodies first (at the start, as CpuSolver's constructor does).
  void update_geometry(bool place = false);
  // Bodies of several members (n_bodies_ > 0): the stages' kernels for them.
  void gather(const ParticleArrays<Real>& p, StepStatus* status);
  void integrate(const ParticleArrays<Real>& p, StepStatus* status);
  /// A step's status read back: a blow-up it flags is reported (RunError).
  void report_failure(const StepStatus& status) const;
  // Run-ahead (docs/performance.md, "Run-ahead"): each step is launched before the host
  // has read the status of the one before it, so that the GPU never waits for the host.
  /// Whether advance() runs ahead: the grid's kept list, and no kernel of the step that
  /// reads what the host decides between steps (periodic cells, bodies, bonds, programs,
  /// MPI ranks; single-domain and decomposition build every step).
  bool runs_ahead() const;
  void advance_ahead(std::int64_t steps);
  /// Launches step `step` of the call that ends at `end` behind the step whose status is
  /// `gate` (null: on the host's word), and the copy of its status to the host.
  void launch_ahead(std::int64_t step, std::int64_t end, const StepStatus* gate);
  /// Reads the launched step step_'s status (waits for it), reports a blow-up, and counts
  /// the step; true when the pair list must be built again.
  bool finish_ahead();
  static int ahead_slot(std::int64_t step) { return 1 + static_cast<int>(step % 3); }
  [[noreturn]] void report_runaway(int particle) const;
  [[noreturn]] void report_body_runaway(int body) const;
  [[noreturn]] void report_penetration(int emitter) const;

  std::size_t n_;
  Method method_;
  ContactFilter filter_;  ///< single-domain's contact test
  Real margin_;  ///< skin on each side of a build box
  StepParams<Real> params_{};
  TimeStep limit_;         ///< dt_crit and what sets it, for the blow-up messages
  std::int64_t step_ = 0;
  double time_ = 0;
  bool rebuild_ = true;
  bool results_ = false;  ///< the pair list holds the results of a step (not after load_state)
  std::string device_name_;
  cudaStream_t stream_ = nullptr;

  DeviceBuffer<physics::LawParameters<Real>> laws_;
  // Motion programs: walls with one (a velocity written after the step, by its own
  // kernel), and servos among them (their walls' forces summed every step).
  DeviceBuffer<MotionProgram> programs_;
  DeviceBuffer<ProgramKnot> program_knots_;
  bool has_programs_ = false;
  bool has_servos_ = false;
  // The step's target of each program when some servo follows a length (length_between):
  // servo_target_kernel fills it in the Gather stage; empty without.
  DeviceBuffer<double> servo_targets_;
  void update_servo_targets(const ParticleArrays<Real>& p);
  /// The per-particle fields (tridem/particle_fields.hpp), and the Model ones on the host
  /// for snapshots.
  ParticleBuffers<Real> d_;
  ModelColumns<Real> host_model_;
  ShownIds shown_ids_;  ///< ParticleModel::shown_ids: the ids the messages name
  /// Bodies, when some has several members (tridem/body_fields.hpp); else 0 and empty.
  std::size_t n_bodies_ = 0;
  BodyBuffers bodies_;
  mutable BodyColumns host_bodies_;  ///< a snapshot's copy of them
  /// Cohesive bonds (docs/fracture.md; empty without): computed with the pair forces,
  /// added by the gather after the pairs, their damage written with the step.
  BondBuffers<Real> bonds_;
  std::unique_ptr<PairListBuilder<Real>> pairs_;
  /// method = decomposition: the pair list is built by sub-domain, every step.
  std::unique_ptr<DecomposedRows<Real>> decomposed_;
  PairArrays<Real> step_pairs_{};  ///< the list of the step in progress
  std::unique_ptr<StageEvents> events_;
  /// Periodic boundaries (physics/periodic_frame.hpp): the cell, the frames of each step in
  /// params_, and with Lees-Edwards the rows' image power (params_.image_power), the
  /// sheared images' slack in the list and the time of the last build.
  PeriodicCell cell_;
  bool periodic_ = false;
  double sheared_slack_ = 0;
  double built_at_ = 0;
  DeviceBuffer<double> image_power_;
  // Statuses: [0] the staged step's (run_stage), [1..3] run-ahead's, one a step in turn;
  // on the host also [4], a fresh status the run-ahead resets its first step's from.
  DeviceBuffer<StepStatus> status_;
  PinnedBuffer<StepStatus> host_status_;
  std::array<cudaEvent_t, 3> ahead_copied_{};  ///< a run-ahead step's status is on the host
  bool run_ahead_ = false;                     ///< SolverConfig::gpu_run_ahead
  std::size_t contact_rows_per_copy_ = 0;      ///< SolverConfig::gpu_contact_rows_per_copy
  std::int64_t ahead_steps_ = 0;               ///< steps launched behind one not yet read
  std::int64_t ahead_held_back_ = 0;  ///< of those, launched again after it asked for a list
  std::function<void()> check_hook_;             ///< MPI ranks only (set_check_hook)
  // The split step (set_ghost_hooks; empty without): the received flags, the hook that
  // takes the ghosts, the last step's slips while the own pass overwrites theirs (restored
  // if a ghost's box left and the list is built again), what it did.
  std::function<void()> take_ghosts_;
  DeviceBuffer<std::uint8_t> received_;
  DeviceBuffer<physics::PairSlip<Real>> slip_backup_;
  bool ghosts_taken_ = true;
  GhostOverlapCounts overlap_counts_;
  mutable PinnedBuffer<unsigned char> staging_;  ///< the shown fields a snapshot copies
  mutable PinnedBuffer<TouchingPair<Real>> touching_;  ///< a snapshot's contacts, as copied
};

}  // namespace tridem::cuda
