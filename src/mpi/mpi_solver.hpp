#pragma once
// The run on N MPI ranks (docs/scaling.md): each rank steps the particles of its strip
// (mpi/strip_plan.hpp) with its local solver (core/rank_solver.hpp: the serial CPU solver,
// or with backend = "cuda" the CUDA solver on the GPU its node-local rank picks,
// mpi/device_choice.hpp), on a copy of the scene that holds them,
// their ghosts and the walls, in global id order. Because the ids keep their order and a
// ghost's state is its owner's, bit for bit, every pair an owned particle takes part in is
// computed as one solver computes it (same emitter, same frame, same history) and summed in
// the same order: the ranks give one rank's results, bit for bit.
//
// Every step: the local step up to its Check; the ranks agree the step is good (else all
// stop at the last good state with one message); the local Integrate; the ghosts' new
// states from their owners (one MPI_Alltoallv of the State fields; on CPU ranks on the
// grid an MPI_Ialltoallv, in flight until the next step has computed the pairs of this
// rank's own particles: docs/scaling.md, "Overlap"); the ranks agree
// whether to stop (a signal on any rank) and whether some particle has moved half the
// skin since the plan. If so, the next step first gathers the whole state (with contact
// history, which therefore migrates with its particles) and plans again, borders moved to
// balance contacts.
//
// Rank 0 drives: the time loop and the outputs run there only, and each call of the
// Solver interface on rank 0 is a command (advance, snapshot, save, load, energy) that
// the other ranks, in serve(), carry out with it. Snapshots, states and energies are
// gathered to rank 0 in global id order, the walls' loads and the elastic energy summed
// there pair by pair in one solver's order; the outputs and checkpoints are one rank's.
#include "core/particle_model.hpp"
#include "core/rank_solver.hpp"
#include "core/time_step.hpp"
#include "mpi/strip_plan.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/solver.hpp"

#include <atomic>
#include <filesystem>
#include <memory>
#include <mpi.h>
#include <string>
#include <tuple>
#include <vector>

namespace tridem::mpi {

/// What the solver refuses on more than one rank, or empty (same on every rank): on GPU
/// ranks when `ranks` is Backend::Cuda (besides, a periodic cell too short for one GPU's
/// list), on CPU ranks otherwise.
std::string refusal(const Scene& scene, const ParticleModel& model, Backend ranks);
/// Why backend = "auto" runs the scene on CPU ranks rather than GPU ranks (a phrase for
/// its note), or empty when GPU ranks run it.
std::string gpu_ranks_decline(const Scene& scene, const ParticleModel& model);
/// The same for the scene's backend (auto: CPU ranks, which every scene can fall back on).
inline std::string refusal(const Scene& scene, const ParticleModel& model) {
  return refusal(scene, model, scene.simulation.backend);
}

template <class Real>
class MpiSolver final : public Solver {
 public:
  /// Collective over `comm`. `os_interrupt` is this process's signal flag; the flag the
  /// ranks agreed on (any rank's signal) is written to `agreed_interrupt`.
  MpiSolver(MPI_Comm comm, const Scene& scene, const ParticleModel& model, const TimeStep& ts,
            const std::atomic<int>* os_interrupt, std::atomic<int>* agreed_interrupt);
  ~MpiSolver() override;  ///< on rank 0: tells the others to stop serving

  void advance(std::int64_t steps) override;
  void snapshot(Snapshot& out, bool with_contacts) const override;
  void save_state(SolverState& out) const override;
  void load_state(const SolverState& in) override;
  /// Every rank writes its slice of the file side by side (mpi/parallel_checkpoint.cpp).
  void save_checkpoint(const std::filesystem::path& file, const CheckpointMeta& meta,
                       Checkpoint& scratch) const override;
  EnergyBudget energy() const override;
  std::int64_t step() const override { return local_->solver().step(); }
  double time() const override { return local_->solver().time(); }
  double dt() const override { return local_->solver().dt(); }
  std::size_t size() const override { return n_; }
  std::string description() const override;
  std::string statistics() const override;
  StageTimes stage_times() const override;
  void set_stage_timing(bool on) override;

  /// Ranks other than 0: carries out rank 0's commands until it stops; true when rank 0
  /// finished without an error.
  bool serve();

 private:
  enum Command : long long {
    kAdvance = 1,
    kSnapshot,
    kSave,
    kLoad,
    kEnergy,
    kCheckpoint,
    kStop,
    kAbort
  };
  /// backend = "auto" (collective): whether the ranks run on GPUs.
  bool auto_takes_gpus(const Scene& scene, const ParticleModel& model) const;
  void order(Command c, long long arg) const;
  void run_steps(std::int64_t steps);
  void step_once();
  void exchange_ghosts();
  /// The overlapped exchange (overlap_): started after a step, completed by the local
  /// solver in the middle of the next (its take hook) or before anything else reads it.
  void start_exchange();
  void finish_exchange();
  void poll_exchange();
  bool drifted() const;
  /// What this rank reports of its local solver's state `ls` (indices into it): its own
  /// particles, the pairs it is the authority for, its bodies and its bonds.
  struct Reported {
    std::vector<std::size_t> particles, pairs, bodies, bonds;
  };
  Reported reported(const SolverState& ls) const;
  /// The records gather_state and the parallel checkpoint send, appended to `to`: local
  /// particle k of `ls` (global id, then its checkpointed fields), pair p (global emitter and
  /// partner, then its slips), body b (global body, then its fields), bond k (its index in
  /// the scene, its points' damage, its released energy).
  void pack_particle(std::vector<double>& to, const SolverState& ls, std::size_t k) const;
  void pack_pair(std::vector<double>& to, const SolverState& ls, std::size_t p) const;
  void pack_body(std::vector<double>& to, const SolverState& ls, std::size_t b) const;
  void pack_bond(std::vector<double>& to, const SolverState& ls, std::size_t k) const;
  /// A pair record (pack_pair) read from `from` at `at`, which it advances.
  using PairRecord =
      std::tuple<std::int32_t, std::int32_t, decltype(SolverState::pair_slip)::value_type>;
  static PairRecord read_pair(const std::vector<double>& from, std::size_t& at);
  /// `pairs` sorted by (emitter, partner), appended to out's contact history.
  static void append_sorted(std::vector<PairRecord>& pairs, SolverState& out);
  /// The whole state on every rank (collective).
  void gather_state(SolverState& out) const;
  /// Collective: this rank's part of checkpoint `file` (its name and `meta` on rank 0 only,
  /// null on the others). The ranks send each particle, pair, body and bond to the rank
  /// whose slice of the file holds it (slices by id), and each writes its slice of every
  /// array where the file has it (io/checkpoint/checkpoint_pieces.hpp, mpi/shared_file.hpp):
  /// the bytes one rank writes, and no rank holds more than its slice.
  void write_checkpoint_part(const std::filesystem::path* file, const CheckpointMeta* meta) const;
  /// A new plan and local solver from the whole state (collective).
  void decompose(const SolverState& whole);
  void build_local(const SolverState& whole);
  void gather_snapshot(Snapshot* out, bool with_contacts) const;
  EnergyBudget gather_energy() const;
  void broadcast_state(SolverState& s) const;
  /// Which rank's copy of pair (a, b) (global ids, a the emitter) is the true one.
  int authority(std::int32_t a, std::int32_t b) const;
  /// Whether this rank reports particle g (state, energy sums, snapshot row): its owner,
  /// or rank 0 for a wall that emits nothing (every rank has the same copy).
  bool reports(std::int32_t g) const {
    const int owner = plan_.owner[static_cast<std::size_t>(g)];
    return owner >= 0 ? owner == rank_ : rank_ == 0;
  }
  /// The pairs' loads on the walls `is_wall` marks (by global id) that this rank is the
  /// authority for, as (wall, 0 = as emitter | 1 = as partner, other, fx, fy, torque).
  template <class Visit, class IsWall>
  std::vector<double> wall_pair_loads(Visit&& visit_pairs, IsWall&& is_wall) const;
  /// From the check hook: each servo wall's load of this step summed across ranks as one
  /// solver sums it, written into the local solver before its programs read it.
  void sum_servo_loads();
  /// Whether this rank reports local body b (state, snapshot row): as its first member.
  bool reports_body(std::size_t b) const {
    return reports(
        static_cast<std::int32_t>(model_.bodies.first[static_cast<std::size_t>(global_body_[b])]));
  }
  std::string global_ids(const std::string& message) const;
  void measure_bandwidth();
  /// f(emitter, partner, result) for each pair of the local solver's last step, by global
  /// ids, in its slot order (none before the first step).
  template <class F>
  void for_each_last_pair(F&& f) const {
    local_->for_each_last_pair(
        [&](std::int32_t e, std::int32_t j, const physics::PairForce<Real>& force) {
          f(global_[static_cast<std::size_t>(e)], global_[static_cast<std::size_t>(j)], force);
        });
  }

  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  Scene scene_;
  ParticleModel model_;
  TimeStep ts_;
  std::size_t n_ = 0;
  double skin_ = 0;
  std::vector<double> radius_;
  const std::atomic<int>* os_interrupt_;
  std::atomic<int>* agreed_interrupt_;

  StripPlan plan_;
  std::vector<std::int32_t> global_;    ///< local index -> global id (ascending)
  std::vector<std::int32_t> local_of_;  ///< global id -> local index, -1 when not held
  std::vector<std::uint8_t> servo_;     ///< global id -> a servo wall (empty: none)
  bool gpu_ = false;                    ///< backend = "cuda": GPU ranks
  int device_ = 0;                      ///< this rank's GPU (GPU ranks)
  std::vector<int> devices_;            ///< every rank's GPU, on rank 0 (GPU ranks)
  std::unique_ptr<RankSolver<Real>> local_;
  bool redecompose_ = false;
  bool check_agreed_ = false;  ///< the check hook ran the step's agreement
  std::string agreed_;         ///< the message the ranks agreed on
  bool timing_ = true;

  // Ghost exchange, sized at each plan: the counts and displacements of each rank's part
  // of the local solver's buffers (RankSolver::set_plan).
  std::vector<int> send_counts_, send_displs_, recv_counts_, recv_displs_;
  // Bodies of several triangles (CPU ranks): each local body's global body, and the body
  // exchange's layout, as the particles'.
  std::vector<std::int32_t> global_body_;
  Scene rank_scene_;                       ///< a rank's scene: settings and its bonds
  std::vector<std::int32_t> global_bond_;  ///< each local bond's index in the scene
  /// Whether this rank reports bond k (of the scene): the authority of its pair.
  bool reports_bond(std::size_t k) const {
    return authority(static_cast<std::int32_t>(scene_.bonds[k].a),
                     static_cast<std::int32_t>(scene_.bonds[k].b)) == rank_;
  }
  std::vector<int> body_send_counts_, body_send_displs_, body_recv_counts_, body_recv_displs_;
  // The overlapped exchange (docs/scaling.md, "Overlap"; CPU ranks on the grid, not
  // periodic): MPI_Ialltoallv of the particles' and the bodies' states, in flight from the
  // end of a step to the middle of the next.
  bool overlap_ = false;
  bool in_flight_ = false;
  MPI_Request requests_[2] = {MPI_REQUEST_NULL, MPI_REQUEST_NULL};
  GhostOverlapCounts earlier_overlap_;  ///< of the local solvers replaced by new plans
  double exchange_wait_ = 0;            ///< seconds in the ghost exchange's MPI calls that wait

  StageTimes earlier_times_;  ///< of the local solvers replaced by new plans
  std::int64_t plans_ = 0;
  double bandwidth_ = 0;  ///< bytes/s of the first exchange
  // Checkpoints written side by side: how many, their bytes and seconds (rank 0's clock).
  mutable std::int64_t checkpoints_ = 0;
  mutable double checkpoint_bytes_ = 0, checkpoint_seconds_ = 0;
  std::string library_;
  mutable SolverState scratch_state_;
  mutable Snapshot scratch_snapshot_;
};

}  // namespace tridem::mpi
