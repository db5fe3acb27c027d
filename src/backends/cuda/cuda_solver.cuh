#pragma once
// The CUDA solver: the whole time loop on one GPU with the single-source physics. The
// state stays on the GPU; only snapshots (output steps) copy it back. One step is the
// CPU solver's stages (kPipeline) with the same sums in the same order, so that both
// agree to rounding and two runs of one scene agree bit for bit.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/decomposed_rows.cuh"
#include "backends/cuda/pair_list_builder.cuh"
#include "backends/cuda/stage_events.cuh"
#include "core/stage_pipeline.hpp"
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace tridem::cuda {

template <class Real>
class CudaSolver final : public Solver {
 public:
  CudaSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
             const SolverConfig& config);
  ~CudaSolver() override;

  void advance(std::int64_t steps) override;
  void snapshot(Snapshot& out, bool with_contacts) const override;
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

 private:
  void upload_model(const ParticleModel& model);
  ParticleArrays<Real> arrays() const;
  void update_geometry();
  [[noreturn]] void report_runaway(int particle) const;
  [[noreturn]] void report_penetration(int emitter) const;
  /// What a snapshot copies back, in Snapshot's order: position, angle, velocities (the
  /// state, double in every precision), then forces (Real).
  static constexpr int kStateArrays = 6, kForceArrays = 3;
  std::array<const DeviceBuffer<double>*, kStateArrays> state_buffers() const {
    return {&x_, &y_, &theta_, &vx_, &vy_, &w_};
  }
  std::array<const DeviceBuffer<Real>*, kForceArrays> force_buffers() const {
    return {&fx_, &fy_, &torque_};
  }

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

  // Fixed per particle: device and the host copies a snapshot needs.
  DeviceBuffer<Real> offset_x_[3], offset_y_[3];
  DeviceBuffer<Real> mass_, area_, half_size_;
  DeviceBuffer<double> inv_mass_, inv_inertia_;
  DeviceBuffer<int> material_;
  DeviceBuffer<std::uint8_t> free_;
  DeviceBuffer<physics::LawParameters<Real>> laws_;
  std::vector<Vec2<Real>> host_offsets_;  ///< 3 per particle
  std::vector<double> host_mass_, host_inertia_;
  std::vector<int> host_material_;
  std::vector<Motion> host_motion_;
  // State (double in every precision), forces, geometry (vertices about the centroid).
  DeviceBuffer<double> x_, y_, theta_, vx_, vy_, w_;
  DeviceBuffer<Real> fx_, fy_, torque_;
  DeviceBuffer<Real> rel_x_[3], rel_y_[3];
  DeviceBuffer<Real> lo_x_, lo_y_, hi_x_, hi_y_;
  DeviceBuffer<Real> build_lo_x_, build_lo_y_, build_hi_x_, build_hi_y_;
  /// The energy budget's cumulative per-particle sums, and room for the elastic energy of
  /// each row when energy() asks for it.
  DeviceBuffer<double> energy_[kEnergyAccumulators];
  mutable DeviceBuffer<double> row_elastic_;
  std::unique_ptr<PairListBuilder<Real>> pairs_;
  /// method = decomposition: the pair list is built by sub-domain, every step.
  std::unique_ptr<DecomposedRows<Real>> decomposed_;
  PairArrays<Real> step_pairs_{};  ///< the list of the step in progress
  std::unique_ptr<StageEvents> events_;
  DeviceBuffer<StepStatus> status_;
  PinnedBuffer<StepStatus> host_status_;
  mutable PinnedBuffer<double> staging_;       ///< the state_buffers() a snapshot copies
  mutable PinnedBuffer<Real> force_staging_;   ///< and its force_buffers()
};

}  // namespace tridem::cuda
