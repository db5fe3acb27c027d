// A GPU rank's local solver (core/rank_solver.hpp, docs/scaling.md): the CudaSolver on this
// rank's GPU, its step split at the Check (kRankPipeline), and its ghosts' states packed on
// the GPU into one contiguous buffer per exchange, staged through pinned host memory for
// MPI (no CUDA-aware MPI yet), and written back by one kernel, after which the solver
// recomputes the geometry and the rebuild test of the new state; bodies' States the same
// way beside them; a servo wall's pairs listed on the GPU for the ranks' sum of its load.
#include "backends/cuda/cuda_backend.hpp"
#include "backends/cuda/cuda_solver.cuh"
#include "core/rank_solver.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <type_traits>

namespace tridem::cuda {

namespace {

constexpr int kBlock = 256;
constexpr int kMaxColumns = 8;

int blocks(std::size_t items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

/// Device columns of double, passed by value: the State arrays, or the centroid.
struct Columns {
  double* a[kMaxColumns];
  int count;
};

/// out[q * count + k] = column k of particle index[q].
__global__ void pack_kernel(Columns c, const int* index, int n, double* out) {
  const int q = blockIdx.x * blockDim.x + threadIdx.x;
  if (q >= n) return;
  const int i = index[q];
  for (int k = 0; k < c.count; ++k) out[q * c.count + k] = c.a[k][i];
}

/// Column k of particle index[q] = in[q * count + k].
__global__ void unpack_kernel(Columns c, const int* index, int n, const double* in) {
  const int q = blockIdx.x * blockDim.x + threadIdx.x;
  if (q >= n) return;
  const int i = index[q];
  for (int k = 0; k < c.count; ++k) c.a[k][i] = in[q * c.count + k];
}

/// Flags an own particle that moved more than sqrt(limit2) from its reference (x, y pairs),
/// or whose centroid is not finite: CpuRank::drifted's test, the move through a periodic
/// boundary (period_x or period_y > 0) the shortest one.
__global__ void drift_kernel(const double* x, const double* y, const int* own, int n,
                             const double* ref, double limit2, double period_x, double period_y,
                             int* flag) {
  const int q = blockIdx.x * blockDim.x + threadIdx.x;
  if (q >= n) return;
  const int i = own[q];
  double dx = x[i] - ref[2 * q], dy = y[i] - ref[2 * q + 1];
  if (period_x > 0) dx = remainder(dx, period_x);
  if (period_y > 0) dy = remainder(dy, period_y);
  if (!(dx * dx + dy * dy <= limit2)) atomicOr(flag, 1);
}

template <class Real>
Columns state_columns(ParticleArrays<Real> p) {
  Columns c{};
  for_each_particle_field([&](auto field) {
    using Field = decltype(field);
    if constexpr (Field::role == FieldRole::State) {
      static_assert(std::is_same_v<typename Field::template type<Real>, double>,
                    "the State fields are double in every precision");
      for_each_array(p.column(field), [&](double* pointer, int) { c.a[c.count++] = pointer; });
    }
  });
  return c;
}

/// The State arrays of the bodies (body_x, ..., body_w): what a ghost body takes from
/// its owner, as CPU ranks send it.
Columns body_state_columns(BodyArrays b) {
  Columns c{};
  for_each_body_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State) c.a[c.count++] = b.column(field);
  });
  return c;
}

std::vector<int> as_int(const std::vector<std::int32_t>& v) { return {v.begin(), v.end()}; }

/// A pair of the step in progress with a servo wall, as marked_pairs_kernel lists it.
template <class Real>
struct MarkedPair {
  int slot, emitter, partner;
  physics::PairLoad<Real> load;
};

/// Appends (in any order) every pair of the step whose emitter or partner `mask` marks.
template <class Real>
__global__ void marked_pairs_kernel(PairArrays<Real> q, const std::uint8_t* mask,
                                    MarkedPair<Real>* out, int* count) {
  const int s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= q.count) return;
  const int e = q.emitter[s], j = q.partner[s];
  if (mask[e] == 0 && mask[j] == 0) return;
  out[atomicAdd(count, 1)] = {s, e, j, q.load[s]};
}

}  // namespace

template <class Real>
class CudaRank final : public RankSolver<Real> {
 public:
  CudaRank(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
           const SolverConfig& config)
      : solver_(scene, model, ts, config) {
    const PeriodicCell& cell = scene.simulation.periodic;
    if (cell.x) period_x_ = cell.x->length();
    if (cell.y) period_y_ = cell.y->length();
    const std::vector<std::uint8_t> servo = servo_wall_mask(model);
    if (!servo.empty()) {
      servo_.upload(servo);
      marked_count_.allocate(1);
      host_marked_count_.allocate(1);
    }
    flag_.allocate(1);
    host_flag_.allocate(1);
  }

  Solver& solver() override { return solver_; }
  const Solver& solver() const override { return solver_; }
  void set_check_hook(std::function<void()> hook) override {
    solver_.set_check_hook(std::move(hook));
  }

  void set_plan(const std::vector<std::int32_t>& send, const std::vector<std::int32_t>& receive,
                const std::vector<std::int32_t>& own) override {
    const auto per = static_cast<std::size_t>(state_array_count());
    sent_ = send.size();
    received_ = receive.size();
    owned_ = own.size();
    receive_host_ = receive;
    send_index_.upload(as_int(send));
    receive_index_.upload(as_int(receive));
    own_index_.upload(as_int(own));
    device_send_.allocate(per * sent_);
    device_receive_.allocate(per * received_);
    host_send_.allocate(per * sent_);
    host_receive_.allocate(per * received_);
    reference_.allocate(2 * owned_);
    const ParticleArrays<Real> p = solver_.device_arrays();
    if (owned_ > 0) {
      Columns centroid{{p.x, p.y}, 2};
      pack_kernel<<<blocks(owned_), kBlock, 0, solver_.stream()>>>(
          centroid, own_index_.data(), static_cast<int>(owned_), reference_.data());
      TRIDEM_CUDA_CHECK_LAUNCH("pack_kernel");
    }
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(solver_.stream()));
  }
  double* send_buffer() override { return host_send_.data(); }
  double* receive_buffer() override { return host_receive_.data(); }

  // The split step (docs/scaling.md, "Overlap"): the own particles' pairs on the GPU while
  // the host completes the exchange in `take` (the GPU needs no polling of MPI meanwhile).
  bool take_ghosts_mid_step(const std::function<void()>& take,
                            const std::function<void()>& poll) override {
    (void)poll;
    if (!solver_.can_take_ghosts_mid_step()) return false;
    std::vector<std::uint8_t> received(solver_.size(), 0);
    for (std::int32_t i : receive_host_) received[static_cast<std::size_t>(i)] = 1;
    solver_.set_ghost_hooks(received, take);
    return true;
  }
  GhostOverlapCounts overlap_counts() const override { return solver_.overlap_counts(); }

  void pack() override {
    const cudaStream_t stream = solver_.stream();
    if (bodies_sent_ > 0) {
      pack_kernel<<<blocks(bodies_sent_), kBlock, 0, stream>>>(
          body_state_columns(solver_.device_body_arrays()), body_send_index_.data(),
          static_cast<int>(bodies_sent_), device_body_send_.data());
      TRIDEM_CUDA_CHECK_LAUNCH("pack_kernel (bodies)");
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_body_send_.data(), device_body_send_.data(),
                                        host_body_send_.size() * sizeof(double),
                                        cudaMemcpyDeviceToHost, stream));
    }
    if (sent_ > 0) {
      const Columns c = state_columns(solver_.device_arrays());
      pack_kernel<<<blocks(sent_), kBlock, 0, stream>>>(
          c, send_index_.data(), static_cast<int>(sent_), device_send_.data());
      TRIDEM_CUDA_CHECK_LAUNCH("pack_kernel");
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_send_.data(), device_send_.data(),
                                        host_send_.size() * sizeof(double), cudaMemcpyDeviceToHost,
                                        stream));
    }
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
  }

  void unpack() override {
    const cudaStream_t stream = solver_.stream();
    if (received_ > 0) {
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(device_receive_.data(), host_receive_.data(),
                                        host_receive_.size() * sizeof(double),
                                        cudaMemcpyHostToDevice, stream));
      const Columns c = state_columns(solver_.device_arrays());
      unpack_kernel<<<blocks(received_), kBlock, 0, stream>>>(
          c, receive_index_.data(), static_cast<int>(received_), device_receive_.data());
      TRIDEM_CUDA_CHECK_LAUNCH("unpack_kernel");
    }
    if (bodies_received_ > 0) {
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(device_body_receive_.data(), host_body_receive_.data(),
                                        host_body_receive_.size() * sizeof(double),
                                        cudaMemcpyHostToDevice, stream));
      unpack_kernel<<<blocks(bodies_received_), kBlock, 0, stream>>>(
          body_state_columns(solver_.device_body_arrays()), body_receive_index_.data(),
          static_cast<int>(bodies_received_), device_body_receive_.data());
      TRIDEM_CUDA_CHECK_LAUNCH("unpack_kernel (bodies)");
    }
    // Every step, ghosts or not: the solver's own rebuild test is read here (kRankPipeline).
    solver_.state_written();
  }

  bool drifted(double limit) const override {
    if (owned_ == 0) return false;
    const cudaStream_t stream = solver_.stream();
    const ParticleArrays<Real> p = solver_.device_arrays();
    TRIDEM_CUDA_CHECK(cudaMemsetAsync(flag_.data(), 0, sizeof(int), stream));
    drift_kernel<<<blocks(owned_), kBlock, 0, stream>>>(
        p.x, p.y, own_index_.data(), static_cast<int>(owned_), reference_.data(), limit * limit,
        period_x_, period_y_, flag_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("drift_kernel");
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_flag_.data(), flag_.data(), sizeof(int),
                                      cudaMemcpyDeviceToHost, stream));
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
    return *host_flag_.data() != 0;
  }

  void energy_sums(std::vector<double>& out) const override {
    const std::size_t n = solver_.size();
    const ParticleArrays<Real> p = solver_.device_arrays();
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(solver_.stream()));
    std::vector<double> column(n);
    out.assign(n * kEnergyAccumulators, 0.0);
    for (int k = 0; k < kEnergyAccumulators; ++k) {
      if (n > 0)
        TRIDEM_CUDA_CHECK(
            cudaMemcpy(column.data(), p.energy[k], n * sizeof(double), cudaMemcpyDeviceToHost));
      for (std::size_t i = 0; i < n; ++i) out[i * kEnergyAccumulators + k] = column[i];
    }
  }

  void for_each_last_pair(const typename RankSolver<Real>::PairVisitor& f) const override {
    std::vector<int> offset, partner;
    std::vector<physics::PairForce<Real>> result;
    if (!solver_.last_pairs(offset, partner, result)) return;
    for (std::size_t e = 0; e + 1 < offset.size(); ++e)
      for (int s = offset[e]; s < offset[e + 1]; ++s)
        f(static_cast<std::int32_t>(e), partner[static_cast<std::size_t>(s)],
          result[static_cast<std::size_t>(s)]);
  }

  // Bodies of several triangles: their State packed and written on the GPU, beside their
  // members' (pack, unpack).
  void set_body_plan(const std::vector<std::int32_t>& send,
                     const std::vector<std::int32_t>& receive) override {
    constexpr auto per = static_cast<std::size_t>(RankSolver<Real>::kBodyStateArrays);
    bodies_sent_ = send.size();
    bodies_received_ = receive.size();
    body_send_index_.upload(as_int(send));
    body_receive_index_.upload(as_int(receive));
    device_body_send_.allocate(per * bodies_sent_);
    device_body_receive_.allocate(per * bodies_received_);
    host_body_send_.allocate(per * bodies_sent_);
    host_body_receive_.allocate(per * bodies_received_);
  }
  double* body_send_buffer() override { return host_body_send_.data(); }
  void bond_terms(const std::function<void(std::size_t, double, double)>& f) const override {
    std::vector<double> elastic, released;
    solver_.bond_terms(elastic, released);
    for (std::size_t k = 0; k < elastic.size(); ++k) f(k, elastic[k], released[k]);
  }
  double* body_receive_buffer() override { return host_body_receive_.data(); }

  // Servo walls: MpiSolver sums each one's load across the ranks from the pairs that
  // reach it (the only ones it asks for: a GPU rank visits those alone, listed on the GPU,
  // in slot order), and writes the sum where the servo's law reads it.
  void for_each_step_pair(const typename RankSolver<Real>::PairVisitor& f) const override {
    const PairArrays<Real> q = solver_.step_pair_arrays();
    if (servo_.size() == 0 || q.count == 0) return;
    const cudaStream_t stream = solver_.stream();
    if (marked_.size() < static_cast<std::size_t>(q.count))
      marked_.allocate(static_cast<std::size_t>(q.count));
    TRIDEM_CUDA_CHECK(cudaMemsetAsync(marked_count_.data(), 0, sizeof(int), stream));
    marked_pairs_kernel<Real><<<blocks(static_cast<std::size_t>(q.count)), kBlock, 0, stream>>>(
        q, servo_.data(), marked_.data(), marked_count_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("marked_pairs_kernel");
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_marked_count_.data(), marked_count_.data(), sizeof(int),
                                      cudaMemcpyDeviceToHost, stream));
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
    std::vector<MarkedPair<Real>> pairs(static_cast<std::size_t>(*host_marked_count_.data()));
    if (!pairs.empty())
      TRIDEM_CUDA_CHECK(cudaMemcpy(pairs.data(), marked_.data(),
                                   pairs.size() * sizeof(MarkedPair<Real>),
                                   cudaMemcpyDeviceToHost));
    std::sort(pairs.begin(), pairs.end(),
              [](const MarkedPair<Real>& a, const MarkedPair<Real>& b) { return a.slot < b.slot; });
    for (const MarkedPair<Real>& m : pairs)
      f(m.emitter, m.partner, physics::joined(m.load, physics::PairDetail<Real>{}));
  }
  void set_load(std::int32_t i, Vec2<Real> force, Real torque) override {
    const ParticleArrays<Real> p = solver_.device_arrays();
    const Real values[3] = {force.x, force.y, torque};
    Real* const to[3] = {p.fx + i, p.fy + i, p.torque + i};
    for (int k = 0; k < 3; ++k)
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(to[k], &values[k], sizeof(Real), cudaMemcpyHostToDevice,
                                        solver_.stream()));
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(solver_.stream()));
  }

  void elastic_terms(
      const std::function<void(std::int32_t, std::int32_t, double)>& f) const override {
    // CudaSolver::energy adds each row's sum, rows ascending.
    std::vector<double> rows;
    solver_.row_elastic(rows);
    for (std::size_t e = 0; e < rows.size(); ++e) f(static_cast<std::int32_t>(e), -1, rows[e]);
  }

  std::string transport() const override {
    return "packed on the GPU, staged through pinned host memory (not CUDA-aware)";
  }

 private:
  CudaSolver<Real> solver_;
  std::size_t sent_ = 0, received_ = 0, owned_ = 0;
  std::vector<std::int32_t> receive_host_;  ///< the received particles (the split step's flags)
  DeviceBuffer<int> send_index_, receive_index_, own_index_;
  DeviceBuffer<double> device_send_, device_receive_;
  PinnedBuffer<double> host_send_, host_receive_;
  DeviceBuffer<double> reference_;  ///< own particles' centroids at the plan, (x, y) pairs
  double period_x_ = 0, period_y_ = 0;  ///< of a periodic cell, 0 along an open axis
  std::size_t bodies_sent_ = 0, bodies_received_ = 0;
  DeviceBuffer<int> body_send_index_, body_receive_index_;
  DeviceBuffer<double> device_body_send_, device_body_receive_;
  PinnedBuffer<double> host_body_send_, host_body_receive_;
  DeviceBuffer<std::uint8_t> servo_;    ///< servo walls among the local particles (or empty)
  mutable DeviceBuffer<MarkedPair<Real>> marked_;
  mutable DeviceBuffer<int> marked_count_;
  mutable PinnedBuffer<int> host_marked_count_;
  mutable DeviceBuffer<int> flag_;
  mutable PinnedBuffer<int> host_flag_;
};

}  // namespace tridem::cuda

namespace tridem {

template <class Real>
std::unique_ptr<RankSolver<Real>> make_cuda_rank(const Scene& scene, const ParticleModel& model,
                                                 const TimeStep& ts, const SolverConfig& config) {
  return std::make_unique<cuda::CudaRank<Real>>(scene, model, ts, config);
}

template std::unique_ptr<RankSolver<float>> make_cuda_rank(const Scene&, const ParticleModel&,
                                                           const TimeStep&, const SolverConfig&);
template std::unique_ptr<RankSolver<double>> make_cuda_rank(const Scene&, const ParticleModel&,
                                                            const TimeStep&, const SolverConfig&);

}  // namespace tridem
