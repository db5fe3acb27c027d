#include "backends/cuda/cuda_solver.cuh"

#include "backends/cuda/body_kernels.cuh"
#include "backends/cuda/bond_kernels.cuh"
#include "backends/cuda/cuda_backend.hpp"
#include "backends/cuda/step_kernels.cuh"
#include "broadphase/candidate_pairs.hpp"
#include "core/memory_estimate.hpp"
#include "core/runaway_message.hpp"
#include "core/snapshot_fill.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace tridem::cuda {

namespace {

constexpr int kBlock = 256;

int blocks(std::size_t items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

/// Bytes an array of n values of T takes in the snapshot's staging: each array starts
/// 8-byte aligned.
template <class T>
std::size_t staged_bytes(std::size_t n) {
  return (n * sizeof(T) + 7) / 8 * 8;
}

/// The staging of the shown fields of n particles.
template <class Real>
std::size_t staging_bytes(std::size_t n) {
  std::size_t bytes = 0;
  Snapshot::for_each_field([&](auto field) {
    using Field = decltype(field);
    bytes += Field::count * staged_bytes<typename Field::template type<Real>>(n);
  });
  return bytes;
}

}  // namespace

template <class Real>
CudaSolver<Real>::CudaSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
                             const SolverConfig& config)
    : n_(model.size()),
      method_(scene.simulation.method),
      host_model_(model),
      shown_ids_(model.shown_ids),
      run_ahead_(config.gpu_run_ahead),
      contact_rows_per_copy_(config.gpu_contact_rows_per_copy > 0 ? config.gpu_contact_rows_per_copy
                                                                  : kContactRowsPerCopy) {
  if (n_ > static_cast<std::size_t>(INT_MAX / 8))
    throw RunError("the CUDA backend handles at most " + std::to_string(INT_MAX / 8) +
                   " particles on one GPU");
  // The caller's GPU (make_solver checked the index): every allocation, stream and kernel
  // of this solver goes to the device current on this host thread from here on.
  TRIDEM_CUDA_CHECK(cudaSetDevice(config.device));
  cudaDeviceProp prop{};
  TRIDEM_CUDA_CHECK(cudaGetDeviceProperties(&prop, config.device));
  device_name_ = prop.name;
  // Refuse before allocating anything: a scene whose particles and bonds do not fit says so
  // up front. The pair slots are sized by the first list's count (PairListBuilder), which
  // refuses in the same words if they do not fit.
  const std::size_t need = gpu_solver_bytes(n_, 0, scene.simulation.precision, scene.bonds.size());
  std::size_t free_bytes = 0, total_bytes = 0;
  TRIDEM_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  if (need > free_bytes)
    throw RunError("the scene needs about " + mebibytes(need) + " of GPU memory for " +
                   std::to_string(n_) + " particles" +
                   (scene.bonds.empty() ? std::string()
                                        : " and " + std::to_string(scene.bonds.size()) + " bonds") +
                   ", but the GPU (" + device_name_ + ") has " + mebibytes(free_bytes) +
                   " free of " + mebibytes(total_bytes) + ": use precision = \"" +
                   std::string(precision_name(Precision::Float)) +
                   "\", fewer particles, or backend = \"" +
                   std::string(backend_name(Backend::OpenMP)) + "\"");
  TRIDEM_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
  events_ = std::make_unique<StageEvents>(stream_);

  params_.dt = ts.chosen;
  limit_ = ts;
  params_.gravity = scene.simulation.gravity;
  params_.local_damping = scene.simulation.local_damping;
  params_.n_materials = static_cast<int>(scene.materials.size());
  params_.max_depth = static_cast<Real>(scene.simulation.max_penetration);
  params_.walls_move = walls_move(model);
  std::vector<physics::LawParameters<Real>> laws;
  for (const auto& law : contact_law_table(scene.materials))
    laws.push_back(physics::SceneContactLaw::cast<Real>(law));
  laws_.upload(laws);
  params_.laws = laws_.data();
  has_programs_ = !model.programs.empty();
  for (const MotionProgram& program : model.programs)
    has_servos_ = has_servos_ || program.kind == ProgramKind::Servo;
  if (has_programs_) {
    programs_.upload(model.programs);
    if (!model.program_knots.empty()) program_knots_.upload(model.program_knots);
  }
  if (std::any_of(model.programs.begin(), model.programs.end(), physics::follows_length))
    servo_targets_.upload(std::vector<double>(model.programs.size(), 0.0));
  params_.programs = {programs_.data(), program_knots_.data(),
                      servo_targets_.size() > 0 ? servo_targets_.data() : nullptr};
  params_.time_new = physics::time_after_step(0, params_.dt);
  // The snapshots' staging, page-locked, carries the initial upload first.
  staging_.allocate(staging_bytes<Real>(n_));
  d_.upload_initial(model, staging_, stream_);
  if (!model.bodies.empty()) {
    n_bodies_ = model.bodies.size();
    bodies_.upload_initial(model.bodies, n_);
  }
  if (!scene.bonds.empty())
    bonds_.upload(initial_bond_columns<Real>(build_bond_model(scene, model)));

  const GridClasses classes = classify_for_grid(model.longest_edge, model.motion);
  margin_ = static_cast<Real>(scene.simulation.skin * classes.cell);
  filter_ = {scene.simulation.contact_test, scene.simulation.bbox_prefilter};
  pairs_ = std::make_unique<PairListBuilder<Real>>(
      classes.small, method_, static_cast<Real>(classes.cell) + 2 * margin_, filter_, 0, stream_);
  cell_ = scene.simulation.periodic;
  periodic_ = cell_.any();
  if (periodic_) {
    // Lees-Edwards: the images above and below slide by γ̇·Ly·dt a step; the list keeps
    // them while they have slid less than the skin (images_slid), so the build lists them
    // within a skin's slack.
    sheared_slack_ = cell_.shear_rate != 0 ? static_cast<double>(margin_) : 0.0;
    pairs_->set_periodic(sheared_slack_);
    if (cell_.shear_rate != 0) {
      image_power_.upload(std::vector<double>(n_, 0.0));
      params_.image_power = image_power_.data();
    }
  }
  if (method_ == Method::Decomposition)
    decomposed_ = std::make_unique<DecomposedRows<Real>>(scene.simulation, classes, stream_);
  status_.allocate(4);
  host_status_.allocate(5);
  host_status_.data()[4] = StepStatus::fresh();
  for (cudaEvent_t& e : ahead_copied_)
    TRIDEM_CUDA_CHECK(cudaEventCreateWithFlags(&e, cudaEventDisableTiming));
  update_geometry(n_bodies_ > 0);
}

template <class Real>
CudaSolver<Real>::~CudaSolver() {
  events_.reset();
  for (cudaEvent_t e : ahead_copied_)
    if (e) cudaEventDestroy(e);
  if (stream_) cudaStreamDestroy(stream_);
}

template <class Real>
void CudaSolver<Real>::update_geometry(bool place) {
  const StepStatus fresh = StepStatus::fresh();
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(status_.data(), &fresh, sizeof fresh,
                                    cudaMemcpyHostToDevice, stream_));
  if (place) {
    place_members_kernel<Real>
        <<<blocks(n_), kBlock, 0, stream_>>>(arrays(), body_arrays(), status_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("place_members_kernel");
  } else {
    integrate_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(arrays(), PairArrays<Real>{},
                                                               params_, status_.data(), false);
    TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
  }
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  rebuild_ = true;
}

template <class Real>
void CudaSolver<Real>::state_written() {
  integrate_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(arrays(), PairArrays<Real>{}, params_,
                                                             status_.data(), false);
  TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
  StepStatus* host = host_status_.data();
  TRIDEM_CUDA_CHECK(
      cudaMemcpyAsync(host, status_.data(), sizeof *host, cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  rebuild_ = rebuild_ || host->rebuild != 0;
}

template <class Real>
bool CudaSolver<Real>::last_pairs(std::vector<int>& offset, std::vector<int>& partner,
                                  std::vector<physics::PairForce<Real>>& result) const {
  offset.clear();
  partner.clear();
  result.clear();
  if (!results_ || step_ == 0) return false;
  pairs_->download(offset, partner, nullptr, &result);
  return true;
}

template <class Real>
void CudaSolver<Real>::row_elastic(std::vector<double>& rows) const {
  rows.clear();
  if (!results_) return;
  row_elastic_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(
      static_cast<int>(n_), pairs_->arrays(), d_.row_elastic.data());
  TRIDEM_CUDA_CHECK_LAUNCH("row_elastic_kernel");
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  rows.resize(n_);
  d_.row_elastic.download(rows);
}

template <class Real>
void CudaSolver<Real>::advance(std::int64_t steps) {
  if (steps > 0 && runs_ahead()) return advance_ahead(steps);
  for (std::int64_t s = 0; s < steps; ++s) {
    params_.time_new = physics::time_after_step(step_, params_.dt);
    if (periodic_) {  // CpuSolver's frames: the pairs' at the step's start, the wrap's at its end
      params_.frame = periodic_frame_of(cell_, static_cast<double>(step_) * params_.dt);
      params_.frame_new = periodic_frame_of(cell_, params_.time_new);
    }
    params_.details = s + 1 == steps;  // only then are this step's pair results read
    if (check_hook_)
      run_step(*this, kRankPipeline, *events_);
    else
      run_step(*this, kPipeline, *events_);
    ++step_;
    time_ += params_.dt;
  }
}

template <class Real>
void CudaSolver<Real>::run_stage(Stage stage) {
  const ParticleArrays<Real> p = arrays();
  StepStatus* status = status_.data();
  StepStatus* host = host_status_.data();
  switch (stage) {
    case Stage::PairList:
      if (decomposed_) {
        // The paper's sub-domains, every step; in a periodic cell at this step's frame.
        decomposed_->build(p, *pairs_, periodic_ ? &params_.frame : nullptr);
      } else if (take_ghosts_) {
        split_pair_list(p);
      } else if (rebuild_ || pairs_->single_step() || images_slid()) {
        // A single-domain list holds the pairs that pass the contact test at this step's
        // positions only: no skin can keep it valid, so it is rebuilt every step.
        rebuild_list(p);
      }
      step_pairs_ = pairs_->arrays();
      return;
    case Stage::PairForces: {
      *host = StepStatus::fresh();
      TRIDEM_CUDA_CHECK(
          cudaMemcpyAsync(status, host, sizeof *host, cudaMemcpyHostToDevice, stream_));
      if (take_ghosts_ && !ghosts_taken_)
        split_pair_forces(p, status);
      else
        launch_pair_forces(p, status);
      if (bonds_.size() > 0) {  // each bond's force, in the same step as the contacts
        if (periodic_)
          bond_forces_kernel<Real, true>
              <<<blocks(bonds_.size()), kBlock, 0, stream_>>>(p, bond_arrays(), params_.frame);
        else
          bond_forces_kernel<Real>
              <<<blocks(bonds_.size()), kBlock, 0, stream_>>>(p, bond_arrays(), params_.frame);
        TRIDEM_CUDA_CHECK_LAUNCH("bond_forces_kernel");
      }
      if (params_.image_power) {  // Lees-Edwards: the boundary's work through each row
        row_image_power_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_);
        TRIDEM_CUDA_CHECK_LAUNCH("row_image_power_kernel");
      }
      return;
    }
    case Stage::Gather:  // with the Check stage's runaway test of every particle (body)
      if (servo_targets_.size() > 0) update_servo_targets(p);
      if (n_bodies_ > 0) return gather(p, status);
      gather_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status,
                                                              false, bond_arrays());
      TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
      if (has_servos_) {  // a servo's law reads the force on its wall at every step
        gather_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status,
                                                                true, bond_arrays());
        TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
      }
      return;
    case Stage::Integrate:  // with the Geometry stage of the next step
      if (bonds_.size() > 0) {  // the step's damage, unless the step is refused
        commit_bonds_kernel<Real>
            <<<blocks(bonds_.size()), kBlock, 0, stream_>>>(bond_arrays(), status);
        TRIDEM_CUDA_CHECK_LAUNCH("commit_bonds_kernel");
      }
      if (n_bodies_ > 0) return integrate(p, status);
      if (periodic_)
        integrate_kernel<Real, true>
            <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, true);
      else
        integrate_kernel<Real>
            <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, true);
      TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
      if (has_programs_) {  // after every row's energy has read the walls' old velocities
        program_velocity_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, params_, status);
        TRIDEM_CUDA_CHECK_LAUNCH("program_velocity_kernel");
      }
      return;
    case Stage::Check:
      TRIDEM_CUDA_CHECK(
          cudaMemcpyAsync(host, status, sizeof *host, cudaMemcpyDeviceToHost, stream_));
      TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
      report_failure(*host);
      if (take_ghosts_ && host->ghost_touch != 0) ++overlap_counts_.ghost_contacts;
      if (check_hook_) {  // before Integrate (kRankPipeline): state_written reads the rebuild
        check_hook_();
        results_ = true;
        return;
      }
      rebuild_ = host->rebuild != 0;
      results_ = true;
      return;
    case Stage::Geometry:  // fused into Integrate (and run by update_geometry at the start)
      return;
  }
}

template <class Real>
void CudaSolver<Real>::report_failure(const StepStatus& status) const {
  // The CPU's order: its pair stage stops on a deep pair before the integrator looks.
  if (status.deep != INT_MAX) report_penetration(status.deep);
  if (status.bad != INT_MAX) {
    if (n_bodies_ > 0) report_body_runaway(status.bad);
    report_runaway(status.bad);
  }
}

template <class Real>
bool CudaSolver<Real>::runs_ahead() const {
  return run_ahead_ && n_ > 0 && !check_hook_ && !take_ghosts_ && !decomposed_ &&
         !pairs_->single_step() && !periodic_ && n_bodies_ == 0 && bonds_.size() == 0 &&
         !has_programs_ && margin_ > Real(0);
}

// Run-ahead: step k + 1 is launched behind step k, gated on k's status on the GPU, before
// the host waits for k's status. A step whose predecessor failed or left its list does
// nothing (held_back in every kernel) and is launched again, so every step computes what
// the staged loop computes, bit for bit; but the GPU has the next step queued while the
// host reads a status, instead of idling through a read-back, a wake-up and the next
// launches every step (the stage clock's Check stage, read-back and synchronisation, was
// 15 µs of a 71 µs double step at 10^4 on the H200: bench/results/edge_pieces_2026-12-04_*).
// A step the stage clock samples runs staged, its stages timed as before.
template <class Real>
void CudaSolver<Real>::advance_ahead(std::int64_t steps) {
  const std::int64_t end = step_ + steps;
  bool in_flight = false;  // step step_ is launched and its status unread
  int timed = -1;          // for step step_ when not in flight: -1 not asked yet, else 0 or 1
  auto sampled = [this] { return events_->on && events_->sample_this_step(); };
  auto mark = std::chrono::steady_clock::now();
  while (step_ < end) {
    if (!in_flight) {
      const bool staged = timed >= 0 ? timed == 1 : sampled();
      timed = -1;
      if (staged) {
        params_.time_new = physics::time_after_step(step_, params_.dt);
        params_.details = step_ + 1 == end;
        run_timed_step(*this, kPipeline, *events_);
        ++step_;
        time_ += params_.dt;
        mark = std::chrono::steady_clock::now();
        continue;
      }
      launch_ahead(step_, end, nullptr);
    }
    bool behind = false;  // step step_ + 1 launched behind step_
    if (step_ + 1 < end) {
      if (sampled()) {
        timed = 1;
      } else {
        launch_ahead(step_ + 1, end, status_.data() + ahead_slot(step_));
        behind = true;
      }
    }
    const bool rebuild = finish_ahead();
    if (events_->on) {
      const auto now = std::chrono::steady_clock::now();
      events_->count_untimed_step();
      events_->add_step_wall(now - mark);
      mark = now;
    }
    in_flight = behind && !rebuild;
    if (behind && rebuild) {  // held back: launched again with the new list
      timed = 0;
      ++ahead_held_back_;
    }
  }
}

template <class Real>
void CudaSolver<Real>::launch_ahead(std::int64_t step, std::int64_t end, const StepStatus* gate) {
  const int slot = ahead_slot(step);
  StepStatus* status = status_.data() + slot;
  const ParticleArrays<Real> p = arrays();
  if (gate == nullptr) {
    // On the host's word: the list it asked for, and a fresh status (else the gather of the
    // step before reset it).
    if (rebuild_) rebuild_list(p);
    step_pairs_ = pairs_->arrays();
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(status, host_status_.data() + 4, sizeof *status,
                                      cudaMemcpyHostToDevice, stream_));
  } else {
    ++ahead_steps_;
  }
  params_.time_new = physics::time_after_step(step, params_.dt);
  params_.details = step + 1 == end;
  params_.gate = gate;
  params_.next_status = status_.data() + ahead_slot(step + 1);
  launch_pair_forces(p, status);
  gather_kernel<Real>
      <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, false, bond_arrays());
  TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
  integrate_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, true);
  TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
  params_.gate = nullptr;
  params_.next_status = nullptr;
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_status_.data() + slot, status, sizeof *status,
                                    cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaEventRecord(ahead_copied_[slot - 1], stream_));
}

template <class Real>
bool CudaSolver<Real>::finish_ahead() {
  const int slot = ahead_slot(step_);
  TRIDEM_CUDA_CHECK(cudaEventSynchronize(ahead_copied_[slot - 1]));
  const StepStatus status = host_status_.data()[slot];
  if (status.failed()) {
    // The step behind it did nothing; the reports read the GPU's state once it is done.
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
    report_failure(status);
  }
  ++step_;
  time_ += params_.dt;
  results_ = true;
  rebuild_ = status.rebuild != 0;
  return rebuild_;
}

template <class Real>
void CudaSolver<Real>::launch_pair_forces(const ParticleArrays<Real>& p, StepStatus* status) {
  if (step_pairs_.count == 0) return;
  if (params_.details) {
    if (periodic_)
      launch_pair_forces_with<true, true>(p, status);
    else
      launch_pair_forces_with<true, false>(p, status);
  } else {
    if (periodic_)
      launch_pair_forces_with<false, true>(p, status);
    else
      launch_pair_forces_with<false, false>(p, status);
  }
}

template <class Real>
template <bool kDetails, bool kPeriodic>
void CudaSolver<Real>::launch_pair_forces_with(const ParticleArrays<Real>& p, StepStatus* status) {
  const PairArrays<Real>& q = step_pairs_;
  constexpr int threads = PairKernelShape<Real>::threads;
  const int grid = (q.count + threads - 1) / threads;
  const std::int32_t* member_body = bodies_.member_body.data();
  const physics::BondArrays<Real> bonds = bond_arrays();
  const bool with_bodies = n_bodies_ > 0, with_bonds = bonds_.size() > 0;
  if (with_bodies && with_bonds)
    pair_forces_kernel<Real, kDetails, true, true, kPeriodic>
        <<<grid, threads, 0, stream_>>>(p, q, params_, status, member_body, bonds);
  else if (with_bodies)
    pair_forces_kernel<Real, kDetails, true, false, kPeriodic>
        <<<grid, threads, 0, stream_>>>(p, q, params_, status, member_body, bonds);
  else if (with_bonds)
    pair_forces_kernel<Real, kDetails, false, true, kPeriodic>
        <<<grid, threads, 0, stream_>>>(p, q, params_, status, nullptr, bonds);
  else
    pair_forces_kernel<Real, kDetails, false, false, kPeriodic>
        <<<grid, threads, 0, stream_>>>(p, q, params_, status, nullptr, bonds);
  TRIDEM_CUDA_CHECK_LAUNCH("pair_forces_kernel");
}

template <class Real>
void CudaSolver<Real>::rebuild_list(const ParticleArrays<Real>& p) {
  pairs_->rebuild(p, margin_, params_.frame);
  rebuild_ = false;
  built_at_ = static_cast<double>(step_) * params_.dt;
}

template <class Real>
bool CudaSolver<Real>::can_take_ghosts_mid_step() const {
  return method_ == Method::Grid && !decomposed_ && !pairs_->single_step() && !periodic_ &&
         margin_ > Real(0);
}

template <class Real>
void CudaSolver<Real>::set_ghost_hooks(const std::vector<std::uint8_t>& received,
                                       std::function<void()> take) {
  if (!can_take_ghosts_mid_step() || received.size() != n_)
    throw RunError("internal error: this solver cannot take its ghosts mid-step");
  received_.upload(received);
  // Every pass of the pair kernel flags a touching pair on a ghost (overlap_counts_), the
  // split ones (params_.slots) also skip the other part's slots.
  params_.received = received_.data();
  take_ghosts_ = std::move(take);
  ghosts_taken_ = true;
}

// The split step's PairList stage (docs/scaling.md, "Overlap"). The Integrate kernel of
// the last step tested every box against its build box, the ghosts' provisional ones
// (integrated here without their other ranks' pairs) included: read back, it can only ask
// for a build a step early, never miss one of an own particle. A build needs every box, so
// the ghosts are taken first; a kept list lets the own pairs go first.
template <class Real>
void CudaSolver<Real>::split_pair_list(const ParticleArrays<Real>& p) {
  StepStatus* host = host_status_.data();
  TRIDEM_CUDA_CHECK(
      cudaMemcpyAsync(host, status_.data(), sizeof *host, cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  ++overlap_counts_.steps;
  ghosts_taken_ = false;
  if (!rebuild_ && host->rebuild == 0) return;
  take_ghosts();
  rebuild_list(p);
  ++overlap_counts_.rebuilt;
}

// The split step's pairs on a kept list: the slots of no received particle go to the GPU,
// the host meanwhile completes the exchange (take_ghosts_: MPI_Waitall, the received State
// written, their geometry and build-box test read back), then the slots on ghosts. Each
// slot's result depends on its own pair only and the gather sums slots in a fixed order, so
// the two passes give one pass's bits. When a ghost's box left its build box, the list is
// built again and every pair computed on it, from the last step's slips (the own pass has
// overwritten its slots' in place: a copy restores them).
template <class Real>
void CudaSolver<Real>::split_pair_forces(const ParticleArrays<Real>& p, StepStatus* status) {
  const auto count = static_cast<std::size_t>(step_pairs_.count);
  if (slip_backup_.size() < count) slip_backup_.allocate(count + count / 5 + 16);
  if (count > 0)
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(slip_backup_.data(), step_pairs_.slip,
                                      count * sizeof(physics::PairSlip<Real>),
                                      cudaMemcpyDeviceToDevice, stream_));
  params_.slots = kOwnSlots;
  launch_pair_forces(p, status);
  take_ghosts();
  if (rebuild_) {
    if (count > 0)
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(step_pairs_.slip, slip_backup_.data(),
                                        count * sizeof(physics::PairSlip<Real>),
                                        cudaMemcpyDeviceToDevice, stream_));
    StepStatus* host = host_status_.data();
    *host = StepStatus::fresh();  // the own pass's flags go with its results
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(status, host, sizeof *host, cudaMemcpyHostToDevice, stream_));
    rebuild_list(p);
    step_pairs_ = pairs_->arrays();
    params_.slots = kAllSlots;
    launch_pair_forces(p, status);
    ++overlap_counts_.rebuilt;
    ++overlap_counts_.discarded;
  } else {
    params_.slots = kGhostSlots;
    launch_pair_forces(p, status);
    ++overlap_counts_.overlapped;
  }
  params_.slots = kAllSlots;
}

// The received particles' State, their geometry and the rebuild test (state_written, by
// the hook's unpack).
template <class Real>
void CudaSolver<Real>::take_ghosts() {
  take_ghosts_();
  ghosts_taken_ = true;
}

template <class Real>
bool CudaSolver<Real>::images_slid() const {
  if (!params_.image_power) return false;
  const double t = static_cast<double>(step_) * params_.dt;
  return std::abs(params_.frame.shear_velocity) * (t - built_at_) > sheared_slack_;
}

// The servos' targets from the walls' poses of the step's start, before the runaway test
// (in the gathers) and the integration read them.
template <class Real>
void CudaSolver<Real>::update_servo_targets(const ParticleArrays<Real>& p) {
  const auto n = static_cast<int>(servo_targets_.size());
  const BodyArrays b = body_arrays();
  const double* x = n_bodies_ > 0 ? b.body_x : p.x;
  const double* y = n_bodies_ > 0 ? b.body_y : p.y;
  servo_target_kernel<Real><<<blocks(servo_targets_.size()), kBlock, 0, stream_>>>(
      params_, n, x, y, servo_targets_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("servo_target_kernel");
}

// Bodies: the members' sums (free ones), then each free body's, with its runaway test.
template <class Real>
void CudaSolver<Real>::gather(const ParticleArrays<Real>& p, StepStatus* status) {
  gather_kernel<Real, true>
      <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, false, bond_arrays());
  TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
  body_gather_kernel<Real>
      <<<blocks(n_bodies_), kBlock, 0, stream_>>>(p, body_arrays(), params_, status, false);
  TRIDEM_CUDA_CHECK_LAUNCH("body_gather_kernel");
  if (!has_servos_) return;
  // A servo's law reads the force on its body at every step: the walls' sums too.
  gather_kernel<Real, true>
      <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status, true, bond_arrays());
  TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
  body_gather_kernel<Real>
      <<<blocks(n_bodies_), kBlock, 0, stream_>>>(p, body_arrays(), params_, status, true);
  TRIDEM_CUDA_CHECK_LAUNCH("body_gather_kernel");
}

// Bodies: every member's energy row (reading the members' velocities as they were) and
// every body's step, then every member placed on its body, with the geometry of the new
// state.
template <class Real>
void CudaSolver<Real>::integrate(const ParticleArrays<Real>& p, StepStatus* status) {
  if (periodic_) {
    member_energy_kernel<Real, true>
        <<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status);
    TRIDEM_CUDA_CHECK_LAUNCH("member_energy_kernel");
    body_integrate_kernel<Real, true>
        <<<blocks(n_bodies_), kBlock, 0, stream_>>>(p, body_arrays(), params_, status);
    TRIDEM_CUDA_CHECK_LAUNCH("body_integrate_kernel");
  } else {
    member_energy_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status);
    TRIDEM_CUDA_CHECK_LAUNCH("member_energy_kernel");
    body_integrate_kernel<Real>
        <<<blocks(n_bodies_), kBlock, 0, stream_>>>(p, body_arrays(), params_, status);
    TRIDEM_CUDA_CHECK_LAUNCH("body_integrate_kernel");
  }
  place_members_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, body_arrays(), status);
  TRIDEM_CUDA_CHECK_LAUNCH("place_members_kernel");
}

template <class Real>
StageTimes CudaSolver<Real>::stage_times() const {
  StageTimes t = events_->times();
  t.fused_into[static_cast<int>(Stage::Geometry)] = static_cast<int>(Stage::Integrate);
  return t;
}

template <class Real>
void CudaSolver<Real>::report_runaway(int i) const {
  // The state on the GPU is still the last good one; redo the failed step of particle i on
  // the host, with the same physics, to say how fast it would have gone.
  auto at = [i](const auto& buffer) {
    typename std::decay_t<decltype(buffer)>::value_type v;
    TRIDEM_CUDA_CHECK(cudaMemcpy(&v, buffer.data() + i, sizeof v, cudaMemcpyDeviceToHost));
    return v;
  };
  const double x = at(d_.x), y = at(d_.y);
  const physics::Pose<double> pose = physics::stepped_pose(
      physics::Pose<double>{{x, y}, at(d_.theta), {at(d_.vx), at(d_.vy)}, at(d_.w)}, true,
      Vec2<Real>{at(d_.fx), at(d_.fy)}, at(d_.torque), at(d_.inv_mass), at(d_.inv_inertia),
      params_.gravity, params_.local_damping, params_.dt);
  throw RunError(runaway_message(step_ + 1, shown_ids_.of_particle(i), x, y, norm(pose.v),
                                 params_.dt, limit_));
}

template <class Real>
void CudaSolver<Real>::report_body_runaway(int k) const {
  // As report_runaway, for body k: its failed step redone on the host.
  auto at = [k](const auto& buffer) {
    typename std::decay_t<decltype(buffer)>::value_type v;
    TRIDEM_CUDA_CHECK(cudaMemcpy(&v, buffer.data() + k, sizeof v, cudaMemcpyDeviceToHost));
    return v;
  };
  const double x = at(bodies_.body_x), y = at(bodies_.body_y);
  const physics::Pose<double> pose = physics::stepped_pose(
      physics::Pose<double>{{x, y},
                            at(bodies_.body_theta),
                            {at(bodies_.body_vx), at(bodies_.body_vy)},
                            at(bodies_.body_w)},
      true, Vec2d{at(bodies_.body_fx), at(bodies_.body_fy)}, at(bodies_.body_torque),
      at(bodies_.body_inv_mass), at(bodies_.body_inv_inertia), params_.gravity,
      params_.local_damping, params_.dt);
  throw RunError("body id " + std::to_string(shown_ids_.of_body(k)) + ": " +
                 runaway_message(step_ + 1, shown_ids_.of_particle(at(bodies_.body_first)), x, y,
                                 norm(pose.v), params_.dt, limit_));
}

template <class Real>
void CudaSolver<Real>::report_penetration(int emitter) const {
  // The state is still the last good one; the pair list holds this step's results.
  std::vector<int> offset, partner;
  std::vector<physics::PairForce<Real>> result;
  pairs_->download(offset, partner, nullptr, &result);
  int s = offset[emitter];
  while (!(result[s].depth > params_.max_depth)) ++s;
  const int j = partner[s];
  pairs_->clear_details();
  auto position = [this](int i) {
    Vec2d xy;
    TRIDEM_CUDA_CHECK(cudaMemcpy(&xy.x, d_.x.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
    TRIDEM_CUDA_CHECK(cudaMemcpy(&xy.y, d_.y.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
    return xy;
  };
  const Vec2d a = position(emitter), b = position(j);
  const DeepPair pair{
      shown_ids_.of_particle(emitter),     shown_ids_.of_particle(j), a.x, a.y, b.x, b.y,
      static_cast<double>(result[s].depth)};
  throw RunError(penetration_message(step_ + 1, pair, static_cast<double>(params_.max_depth),
                                     static_cast<double>(params_.dt), limit_));
}

template <class Real>
void CudaSolver<Real>::snapshot(Snapshot& out, bool with_contacts) const {
  const std::size_t n = n_;
  if (step_ > 0) {
    // Walls' forces are summed only here: the time loop does not need them.
    gather_kernel<Real><<<blocks(n), kBlock, 0, stream_>>>(arrays(), pairs_->arrays(), params_,
                                                           status_.data(), true, bond_arrays());
    TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
    if (n_bodies_ > 0) {  // and those of fixed and prescribed bodies
      body_gather_kernel<Real><<<blocks(n_bodies_), kBlock, 0, stream_>>>(
          arrays(), body_arrays(), params_, status_.data(), true);
      TRIDEM_CUDA_CHECK_LAUNCH("body_gather_kernel");
    }
  }
  // The shown fields, each array into its own place of the staging buffer, one
  // synchronisation, then into the snapshot in double.
  std::size_t at = 0;
  Snapshot::for_each_field([&](auto field) {
    using T = typename decltype(field)::template type<Real>;
    for_each_array(d_.column(field), [&](const DeviceBuffer<T>& from, int) {
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(staging_.data() + at, from.data(), n * sizeof(T),
                                        cudaMemcpyDeviceToHost, stream_));
      at += staged_bytes<T>(n);
    });
  });
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  out.step = step_;
  out.time = time_;
  out.resize(n);
  at = 0;
  Snapshot::for_each_field([&](auto field) {
    using T = typename decltype(field)::template type<Real>;
    for_each_array(out.column(field), [&](std::vector<double>& to, int) {
      const auto* from = reinterpret_cast<const T*>(staging_.data() + at);
      const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count > 65536)
      for (std::ptrdiff_t i = 0; i < count; ++i) to[i] = static_cast<double>(from[i]);
      at += staged_bytes<T>(n);
    });
  });
  fill_from_model(out, host_model_);
  if (n_bodies_ > 0) bodies_.download(host_bodies_, n_bodies_, n);  // after the sync above
  fill_bodies(out, host_bodies_, n_bodies_);
  fill_bonds(out, bonds_.download_state());  // after the sync above
  out.periodic = cell_;
  out.contacts.clear();
  out.contact_precision = kPrecisionOf<Real>;
  if (!with_contacts || step_ == 0) return;
  append_touching_contacts(out, static_cast<int>(n), pairs_->arrays(), stream_, out.x.data(),
                           out.y.data(), touching_, contact_rows_per_copy_);
  if (periodic_)
    set_image_shifts(out, periodic_frame_of(cell_, static_cast<double>(step_) * params_.dt),
                     out.x.data(), out.y.data());
}

// The sums are reduced on the host in index order: n doubles per accumulator cross the bus
// at logging steps only, and the result does not depend on the thread schedule.
template <class Real>
EnergyBudget CudaSolver<Real>::energy() const {
  // The accumulators, then (with results) each row's elastic energy.
  const int arrays = kEnergyAccumulators + (results_ ? 1 : 0);
  const auto source = [&](int k) -> const DeviceBuffer<double>& {
    return k < kEnergyAccumulators ? d_.energy[k] : d_.row_elastic;
  };
  if (results_) {
    row_elastic_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(static_cast<int>(n_),
                                                                  pairs_->arrays(),
                                                                  d_.row_elastic.data());
    TRIDEM_CUDA_CHECK_LAUNCH("row_elastic_kernel");
  }
  double totals[kEnergyAccumulators + 1] = {};
  const std::size_t bytes = n_ * sizeof(double);
  // All of them into the snapshots' page-locked staging at once (it holds six doubles a
  // particle and more, these at most five), one synchronisation, each summed on a thread of
  // its own: the same sums in the same order, without a pageable download per array (some
  // 0.2 s a log row at 10^7, issue 12).
  if (staging_.size() < static_cast<std::size_t>(arrays) * bytes)
    throw RunError("internal error: the snapshot staging cannot hold the energy sums");
  for (int k = 0; k < arrays; ++k)
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(staging_.data() + static_cast<std::size_t>(k) * bytes,
                                      source(k).data(), bytes, cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
#pragma omp parallel for schedule(static, 1) if (n_ > 65536)
  for (int k = 0; k < arrays; ++k) {
    const auto* from =
        reinterpret_cast<const double*>(staging_.data() + static_cast<std::size_t>(k) * bytes);
    double total = 0;
    for (std::size_t i = 0; i < n_; ++i) total += from[i];
    totals[k] = total;
  }
  EnergyBudget b;
  b.elastic = totals[kEnergyAccumulators];
  // The CPU's order: the pairs' energy, then the bonds' ascending.
  std::vector<double> bond_elastic, released;
  bond_terms(bond_elastic, released);
  for (double v : bond_elastic) b.elastic += v;
  for (double v : released) b.dissipated_fracture += v;
  b.dissipated_damping = totals[kDissipatedDamping];
  b.dissipated_friction = totals[kDissipatedFriction];
  b.dissipated_local = totals[kDissipatedLocal];
  b.wall_work = totals[kWallWork];
  return b;
}

template <class Real>
void CudaSolver<Real>::bond_terms(std::vector<double>& elastic,
                                  std::vector<double>& released) const {
  elastic.assign(bonds_.size(), 0.0);
  released.assign(bonds_.size(), 0.0);
  if (bonds_.size() == 0) return;
  if (results_) {
    bond_elastic_kernel<Real>
        <<<blocks(bonds_.size()), kBlock, 0, stream_>>>(bond_arrays(), bonds_.elastic.data());
    TRIDEM_CUDA_CHECK_LAUNCH("bond_elastic_kernel");
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
    bonds_.elastic.download(elastic);
  }
  bonds_.d.dissipated.download(released);
}

template <class Real>
std::string CudaSolver<Real>::description() const {
  char skin[64];
  std::snprintf(skin, sizeof skin, ", skin %g", static_cast<double>(margin_));
  return std::string(backend_name(Backend::Cuda)) + " (" + device_name_ + "), " +
         precision_description(sizeof(Real) == 8 ? Precision::Double : Precision::Float) + ", " +
         method_description(method_, filter_.test, filter_.bbox_prefilter) +
         (pairs_->single_step() || decomposed_ ? std::string(", list rebuilt every step")
                                               : std::string(skin));
}

template <class Real>
std::string CudaSolver<Real>::statistics() const {
  char text[160];
  std::snprintf(text, sizeof text, "pair list built %lld times in %lld steps; %d pairs (room for %zu)",
                static_cast<long long>(pairs_->builds()), static_cast<long long>(step_),
                pairs_->count(), pairs_->capacity());
  std::string out = text;
  if (decomposed_) out += "; " + decomposed_->summary();
  if (ahead_steps_ > 0)
    out += "; " + std::to_string(ahead_steps_) + " steps launched ahead of the last one's check (" +
           std::to_string(ahead_held_back_) + " launched again after a list build)";
  return out;
}

template class CudaSolver<float>;
template class CudaSolver<double>;

}  // namespace tridem::cuda

namespace tridem {

bool cuda_available(std::string* reason) {
  int count = 0;
  const cudaError_t error = cudaGetDeviceCount(&count);
  if (error != cudaSuccess) {
    if (reason)
      *reason = std::string("no usable GPU: no NVIDIA driver or device found (CUDA says: ") +
                cudaGetErrorString(error) + ")";
    cudaGetLastError();  // clear it: the CPU backends go on
    return false;
  }
  if (count == 0) {
    if (reason) *reason = "no CUDA device is present";
    return false;
  }
  return true;
}

int cuda_device_count() {
  int count = 0;
  if (!cuda_available() || cudaGetDeviceCount(&count) != cudaSuccess) return 0;
  return count;
}

std::string cuda_device_description(int device) {
  if (device < 0 || device >= cuda_device_count()) return {};
  cudaDeviceProp prop{};
  if (cudaGetDeviceProperties(&prop, device) != cudaSuccess) return {};
  char text[256];
  std::snprintf(text, sizeof text, "%s (sm_%d%d, %d SMs, %.0f GiB)", prop.name, prop.major,
                prop.minor, prop.multiProcessorCount,
                static_cast<double>(prop.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0));
  return text;
}

std::size_t cuda_stream_pool_peak(int device, bool reset) {
  if (device < 0 || device >= cuda_device_count()) return 0;
  cudaMemPool_t pool = nullptr;
  if (cudaDeviceGetDefaultMemPool(&pool, device) != cudaSuccess) return 0;
  unsigned long long peak = 0;  // the attribute is a cuuint64_t
  TRIDEM_CUDA_CHECK(cudaMemPoolGetAttribute(pool, cudaMemPoolAttrUsedMemHigh, &peak));
  if (reset) {
    unsigned long long zero = 0;  // the attribute's only settable value: the current use is kept
    TRIDEM_CUDA_CHECK(cudaMemPoolSetAttribute(pool, cudaMemPoolAttrUsedMemHigh, &zero));
  }
  return static_cast<std::size_t>(peak);
}

std::unique_ptr<Solver> make_cuda_solver(const Scene& scene, const ParticleModel& model,
                                         const TimeStep& ts, const SolverConfig& config) {
  if (scene.simulation.precision == Precision::Float)
    return std::make_unique<cuda::CudaSolver<float>>(scene, model, ts, config);
  return std::make_unique<cuda::CudaSolver<double>>(scene, model, ts, config);
}

std::size_t cuda_solver_bytes(std::size_t n, std::size_t pairs, Precision precision,
                              std::size_t bonds) {
  return gpu_solver_bytes(n, pair_slots_for(pairs), precision, bonds);
}

}  // namespace tridem
