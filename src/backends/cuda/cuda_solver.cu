#include "backends/cuda/cuda_solver.cuh"

#include "backends/cuda/cuda_backend.hpp"
#include "backends/cuda/step_kernels.cuh"
#include "broadphase/candidate_pairs.hpp"
#include "core/runaway_message.hpp"
#include "core/snapshot_fill.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <climits>
#include <cstdio>
#include <limits>
#include <string>

namespace tridem::cuda {

namespace {

constexpr int kBlock = 256;

int blocks(std::size_t items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

template <class Real>
std::vector<Real> to_real(const std::vector<double>& v) {
  return std::vector<Real>(v.begin(), v.end());
}

std::string mib(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

}  // namespace

template <class Real>
CudaSolver<Real>::CudaSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
                             const SolverConfig& config)
    : n_(model.size()), method_(scene.simulation.method) {
  if (n_ > static_cast<std::size_t>(INT_MAX / 8))
    throw RunError("the CUDA backend handles at most " + std::to_string(INT_MAX / 8) +
                   " particles on one GPU");
  // The caller's GPU (make_solver checked the index): every allocation, stream and kernel
  // of this solver goes to the device current on this host thread from here on.
  TRIDEM_CUDA_CHECK(cudaSetDevice(config.device));
  cudaDeviceProp prop{};
  TRIDEM_CUDA_CHECK(cudaGetDeviceProperties(&prop, config.device));
  device_name_ = prop.name;
  // Refuse before allocating anything: a scene that does not fit says so up front.
  const std::size_t reserve = kCudaPairsPerParticle * n_ + 1024;
  const std::size_t need = cuda_solver_bytes(n_, reserve, scene.simulation.precision);
  std::size_t free_bytes = 0, total_bytes = 0;
  TRIDEM_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  if (need > free_bytes)
    throw RunError(
        "the scene needs about " + mib(need) + " of GPU memory for " + std::to_string(n_) +
        " particles, but the GPU (" + device_name_ + ") has " + mib(free_bytes) + " free of " +
        mib(total_bytes) + ": use precision = \"" + std::string(precision_name(Precision::Float)) +
        "\", fewer particles, or backend = \"" + std::string(backend_name(Backend::OpenMP)) + "\"");
  TRIDEM_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
  events_ = std::make_unique<StageEvents>(stream_);

  params_.dt = ts.chosen;
  limit_ = ts;
  params_.gravity = scene.simulation.gravity;
  params_.local_damping = scene.simulation.local_damping;
  params_.n_materials = static_cast<int>(scene.materials.size());
  params_.max_depth = static_cast<Real>(scene.simulation.max_penetration);
  params_.walls_move = false;
  for (std::size_t i = 0; i < n_; ++i)
    params_.walls_move = params_.walls_move ||
                         (model.motion[i] != Motion::Free &&
                          (model.velocity[i].x != 0 || model.velocity[i].y != 0 ||
                           model.angular_velocity[i] != 0));
  std::vector<physics::LawParameters<Real>> laws;
  for (const auto& law : contact_law_table(scene.materials))
    laws.push_back(physics::SceneContactLaw::cast<Real>(law));
  laws_.upload(laws);
  params_.laws = laws_.data();
  upload_model(model);

  const GridClasses classes = classify_for_grid(model.longest_edge, model.motion);
  margin_ = static_cast<Real>(scene.simulation.skin * classes.cell);
  filter_ = {scene.simulation.contact_test, scene.simulation.bbox_prefilter};
  pairs_ = std::make_unique<PairListBuilder<Real>>(
      classes.small, method_, static_cast<Real>(classes.cell) + 2 * margin_, filter_, reserve,
      stream_);
  if (method_ == Method::Decomposition)
    decomposed_ = std::make_unique<DecomposedRows<Real>>(scene.simulation, classes, stream_);
  status_.allocate(1);
  host_status_.allocate(1);
  staging_.allocate(kStateArrays * n_);
  force_staging_.allocate(kForceArrays * n_);
  update_geometry();
}

template <class Real>
CudaSolver<Real>::~CudaSolver() {
  events_.reset();
  if (stream_) cudaStreamDestroy(stream_);
}

template <class Real>
void CudaSolver<Real>::upload_model(const ParticleModel& model) {
  std::vector<Real> ox[3], oy[3], mass(n_), half(n_);
  std::vector<double> inv_mass(n_), inv_inertia(n_);
  std::vector<std::uint8_t> free(n_);
  host_offsets_.resize(3 * n_);
  host_mass_.resize(n_);
  host_inertia_.resize(n_);
  for (int k = 0; k < 3; ++k) {
    ox[k].resize(n_);
    oy[k].resize(n_);
  }
  for (std::size_t i = 0; i < n_; ++i) {
    for (int k = 0; k < 3; ++k) {
      ox[k][i] = static_cast<Real>(model.offsets[i][k].x);
      oy[k][i] = static_cast<Real>(model.offsets[i][k].y);
      host_offsets_[3 * i + k] = {ox[k][i], oy[k][i]};
    }
    free[i] = model.motion[i] == Motion::Free;
    mass[i] = free[i] ? static_cast<Real>(model.mass[i]) : Real(0);
    inv_mass[i] = free[i] ? 1.0 / model.mass[i] : 0.0;
    inv_inertia[i] = free[i] ? 1.0 / model.inertia[i] : 0.0;
    half[i] = static_cast<Real>(0.5 * model.longest_edge[i]);
    // What a snapshot reports, as the CPU solver does: 1/(1/m).
    host_mass_[i] = inv_mass[i] > 0 ? 1.0 / inv_mass[i] : 0.0;
    host_inertia_[i] = inv_inertia[i] > 0 ? 1.0 / inv_inertia[i] : 0.0;
  }
  for (int k = 0; k < 3; ++k) {
    offset_x_[k].upload(ox[k]);
    offset_y_[k].upload(oy[k]);
  }
  inv_mass_.upload(inv_mass);
  inv_inertia_.upload(inv_inertia);
  mass_.upload(mass);
  half_size_.upload(half);
  area_.upload(to_real<Real>(model.area));
  material_.upload(model.material);
  free_.upload(free);
  host_material_ = model.material;
  host_motion_ = model.motion;

  std::vector<double> x(n_), y(n_), vx(n_), vy(n_), w(n_);
  for (std::size_t i = 0; i < n_; ++i) {
    x[i] = model.centroid[i].x;
    y[i] = model.centroid[i].y;
    vx[i] = model.velocity[i].x;
    vy[i] = model.velocity[i].y;
    w[i] = model.angular_velocity[i];
  }
  x_.upload(x);
  y_.upload(y);
  vx_.upload(vx);
  vy_.upload(vy);
  w_.upload(w);
  theta_.upload(std::vector<double>(n_, 0.0));
  const std::vector<Real> zeros(n_, Real(0));
  for (auto* b : {&fx_, &fy_, &torque_}) b->upload(zeros);
  for (int k = 0; k < 3; ++k) {
    rel_x_[k].allocate(n_);
    rel_y_[k].allocate(n_);
  }
  for (auto* b : {&lo_x_, &lo_y_, &hi_x_, &hi_y_}) b->allocate(n_);
  // Until a grid build sets them, the build boxes are the whole plane. A single-domain
  // solver never sets them (it rebuilds every step), so the geometry kernel, which
  // compares every box with its build box, then never raises the rebuild flag: no atomic
  // per particle and step on one word.
  const std::vector<Real> lowest(n_, std::numeric_limits<Real>::lowest());
  const std::vector<Real> highest(n_, std::numeric_limits<Real>::max());
  for (auto* b : {&build_lo_x_, &build_lo_y_}) b->upload(lowest);
  for (auto* b : {&build_hi_x_, &build_hi_y_}) b->upload(highest);
  const std::vector<double> no_energy(n_, 0.0);
  for (auto& b : energy_) b.upload(no_energy);
  row_elastic_.allocate(n_);
}

template <class Real>
ParticleArrays<Real> CudaSolver<Real>::arrays() const {
  ParticleArrays<Real> p;
  p.n = static_cast<int>(n_);
  for (int k = 0; k < 3; ++k) {
    p.offset_x[k] = offset_x_[k].data();
    p.offset_y[k] = offset_y_[k].data();
    p.rel_x[k] = rel_x_[k].data();
    p.rel_y[k] = rel_y_[k].data();
  }
  p.inv_mass = inv_mass_.data();
  p.inv_inertia = inv_inertia_.data();
  p.mass = mass_.data();
  p.area = area_.data();
  p.half_size = half_size_.data();
  p.material = material_.data();
  p.free = free_.data();
  p.x = x_.data();
  p.y = y_.data();
  p.theta = theta_.data();
  p.vx = vx_.data();
  p.vy = vy_.data();
  p.w = w_.data();
  p.fx = fx_.data();
  p.fy = fy_.data();
  p.torque = torque_.data();
  p.lo_x = lo_x_.data();
  p.lo_y = lo_y_.data();
  p.hi_x = hi_x_.data();
  p.hi_y = hi_y_.data();
  p.build_lo_x = build_lo_x_.data();
  p.build_lo_y = build_lo_y_.data();
  p.build_hi_x = build_hi_x_.data();
  p.build_hi_y = build_hi_y_.data();
  for (int k = 0; k < kEnergyAccumulators; ++k) p.energy[k] = energy_[k].data();
  return p;
}

template <class Real>
void CudaSolver<Real>::update_geometry() {
  const StepStatus fresh{0, INT_MAX, INT_MAX};
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(status_.data(), &fresh, sizeof fresh,
                                    cudaMemcpyHostToDevice, stream_));
  integrate_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(arrays(), PairArrays<Real>{},
                                                             params_, status_.data(), false);
  TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  rebuild_ = true;
}

template <class Real>
void CudaSolver<Real>::advance(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) {
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
        decomposed_->build(p, *pairs_);  // the paper's sub-domains, every step
      } else if (rebuild_ || pairs_->single_step()) {
        // A single-domain list holds the pairs that pass the contact test at this step's
        // positions only: no skin can keep it valid, so it is rebuilt every step.
        pairs_->rebuild(p, margin_);
        rebuild_ = false;
      }
      step_pairs_ = pairs_->arrays();
      return;
    case Stage::PairForces: {
      *host = {0, INT_MAX, INT_MAX};
      TRIDEM_CUDA_CHECK(
          cudaMemcpyAsync(status, host, sizeof *host, cudaMemcpyHostToDevice, stream_));
      const PairArrays<Real>& q = step_pairs_;
      if (q.count == 0) return;
      constexpr int threads = PairKernelShape<Real>::threads;
      pair_forces_kernel<Real><<<(q.count + threads - 1) / threads, threads, 0, stream_>>>(
          p, q, params_, status);
      TRIDEM_CUDA_CHECK_LAUNCH("pair_forces_kernel");
      return;
    }
    case Stage::Gather:  // with the Check stage's runaway test of every particle
      gather_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status,
                                                              false);
      TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
      return;
    case Stage::Integrate:  // with the Geometry stage of the next step
      integrate_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(p, step_pairs_, params_, status,
                                                                 true);
      TRIDEM_CUDA_CHECK_LAUNCH("integrate_kernel");
      return;
    case Stage::Check:
      TRIDEM_CUDA_CHECK(
          cudaMemcpyAsync(host, status, sizeof *host, cudaMemcpyDeviceToHost, stream_));
      TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
      // The CPU's order: its pair stage stops on a deep pair before the integrator looks.
      if (host->deep != INT_MAX) report_penetration(host->deep);
      if (host->bad != INT_MAX) report_runaway(host->bad);
      rebuild_ = host->rebuild != 0;
      results_ = true;
      return;
    case Stage::Geometry:  // fused into Integrate (and run by update_geometry at the start)
      return;
  }
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
  double v[kStateArrays];
  Real f[kForceArrays];
  const auto arrays = state_buffers();
  const auto forces = force_buffers();
  for (int k = 0; k < kStateArrays; ++k)
    TRIDEM_CUDA_CHECK(cudaMemcpy(&v[k], arrays[k]->data() + i, sizeof(double), cudaMemcpyDeviceToHost));
  for (int k = 0; k < kForceArrays; ++k)
    TRIDEM_CUDA_CHECK(cudaMemcpy(&f[k], forces[k]->data() + i, sizeof(Real), cudaMemcpyDeviceToHost));
  double inv_mass, inv_inertia;
  TRIDEM_CUDA_CHECK(cudaMemcpy(&inv_mass, inv_mass_.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
  TRIDEM_CUDA_CHECK(cudaMemcpy(&inv_inertia, inv_inertia_.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
  const physics::Pose<double> pose = physics::stepped_pose(
      physics::Pose<double>{{v[0], v[1]}, v[2], {v[3], v[4]}, v[5]}, true,
      Vec2<Real>{f[0], f[1]}, f[2], inv_mass, inv_inertia, params_.gravity,
      params_.local_damping, params_.dt);
  throw RunError(runaway_message(step_ + 1, i, v[0], v[1], norm(pose.v), params_.dt, limit_));
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
  auto position = [this](int i) {
    Vec2d xy;
    TRIDEM_CUDA_CHECK(cudaMemcpy(&xy.x, x_.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
    TRIDEM_CUDA_CHECK(cudaMemcpy(&xy.y, y_.data() + i, sizeof(double), cudaMemcpyDeviceToHost));
    return xy;
  };
  const Vec2d a = position(emitter), b = position(j);
  const DeepPair pair{emitter, j, a.x, a.y, b.x, b.y, static_cast<double>(result[s].depth)};
  throw RunError(penetration_message(step_ + 1, pair, static_cast<double>(params_.max_depth),
                                     static_cast<double>(params_.dt), limit_));
}

template <class Real>
void CudaSolver<Real>::snapshot(Snapshot& out, bool with_contacts) const {
  const std::size_t n = n_;
  if (step_ > 0) {
    // Walls' forces are summed only here: the time loop does not need them.
    gather_kernel<Real><<<blocks(n), kBlock, 0, stream_>>>(arrays(), pairs_->arrays(), params_,
                                                           status_.data(), true);
    TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
  }
  const auto arrays = state_buffers();
  for (int k = 0; k < kStateArrays; ++k)
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(staging_.data() + k * n, arrays[k]->data(),
                                      n * sizeof(double), cudaMemcpyDeviceToHost, stream_));
  const auto forces = force_buffers();
  for (int k = 0; k < kForceArrays; ++k)
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(force_staging_.data() + k * n, forces[k]->data(),
                                      n * sizeof(Real), cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  out.step = step_;
  out.time = time_;
  out.resize(n);
  std::vector<double>* fields[kStateArrays] = {&out.x, &out.y, &out.theta,
                                               &out.vx, &out.vy, &out.omega};
  for (int k = 0; k < kStateArrays; ++k)
    fields[k]->assign(staging_.data() + k * n, staging_.data() + (k + 1) * n);
  std::vector<double>* force_fields[kForceArrays] = {&out.fx, &out.fy, &out.torque};
  for (int k = 0; k < kForceArrays; ++k) {
    const Real* from = force_staging_.data() + k * n;
    std::vector<double>& to = *force_fields[k];
    for (std::size_t i = 0; i < n; ++i) to[i] = static_cast<double>(from[i]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2d off[3] = {{host_offsets_[3 * i].x, host_offsets_[3 * i].y},
                          {host_offsets_[3 * i + 1].x, host_offsets_[3 * i + 1].y},
                          {host_offsets_[3 * i + 2].x, host_offsets_[3 * i + 2].y}};
    set_vertices(out, i, physics::place(Vec2d{out.x[i], out.y[i]}, out.theta[i], off));
  }
  out.mass = host_mass_;
  out.inertia = host_inertia_;
  out.material = host_material_;
  out.motion = host_motion_;
  out.contacts.clear();
  if (!with_contacts || step_ == 0) return;
  std::vector<int> offset, partner;
  std::vector<physics::PairForce<Real>> result;
  pairs_->download(offset, partner, nullptr, &result);
  append_contacts(out, n, offset.data(), partner.data(), result.data(), out.x.data(),
                  out.y.data());
}

// The sums are reduced on the host in index order: n doubles per accumulator cross the bus
// at logging steps only, and the result does not depend on the thread schedule.
template <class Real>
EnergyBudget CudaSolver<Real>::energy() const {
  std::vector<double> sums(n_);
  double totals[kEnergyAccumulators + 1] = {};
  if (results_) {
    row_elastic_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(static_cast<int>(n_),
                                                                  pairs_->arrays(),
                                                                  row_elastic_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("row_elastic_kernel");
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
    row_elastic_.download(sums);
    for (double v : sums) totals[kEnergyAccumulators] += v;
  }
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  for (int k = 0; k < kEnergyAccumulators; ++k) {
    energy_[k].download(sums);
    for (double v : sums) totals[k] += v;
  }
  EnergyBudget b;
  b.elastic = totals[kEnergyAccumulators];
  b.dissipated_damping = totals[kDissipatedDamping];
  b.dissipated_friction = totals[kDissipatedFriction];
  b.dissipated_local = totals[kDissipatedLocal];
  b.wall_work = totals[kWallWork];
  return b;
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
  if (decomposed_) return std::string(text) + "; " + decomposed_->summary();
  return text;
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

std::unique_ptr<Solver> make_cuda_solver(const Scene& scene, const ParticleModel& model,
                                         const TimeStep& ts, const SolverConfig& config) {
  if (scene.simulation.precision == Precision::Float)
    return std::make_unique<cuda::CudaSolver<float>>(scene, model, ts, config);
  return std::make_unique<cuda::CudaSolver<double>>(scene, model, ts, config);
}

namespace {

template <class Real>
std::size_t bytes_for(std::size_t n, std::size_t pairs) {
  // Per particle: 26 reals (offsets, mass terms, forces, vertices, two boxes) and 8
  // doubles (state, inverse mass and inertia), 5 doubles of energy sums, flags and
  // material, the grid (keys, indices, 4 cells of start and end), the row offsets (new,
  // old, reverse, counts); pinned host staging is not GPU memory.
  const std::size_t per_particle =
      26 * sizeof(Real) + 8 * 8 + 5 * 8 + 4 + 2 + 4 * 4 + 4 * 2 * 4 + 4 * 4;
  // Per pair: partner and slip twice (new and old list), emitter, slot id, result,
  // reverse sort keys and slots, and CUB's sort scratch (keys and values).
  const std::size_t per_pair = 2 * (4 + sizeof(physics::PairSlip<Real>)) + 4 + 4 +
                               sizeof(physics::PairForce<Real>) + 4 + 4 + 8;
  return n * per_particle + pairs * per_pair + (16u << 20);
}

}  // namespace

std::size_t cuda_solver_bytes(std::size_t n, std::size_t pairs, Precision precision) {
  return precision == Precision::Float ? bytes_for<float>(n, pairs) : bytes_for<double>(n, pairs);
}

}  // namespace tridem
