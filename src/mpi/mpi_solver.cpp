#include "mpi/mpi_solver.hpp"

#include "backends/cuda/cuda_backend.hpp"
#include "core/particle_columns.hpp"
#include "core/periodic_checks.hpp"
#include "mpi/agreement.hpp"
#include "mpi/collectives.hpp"
#include "mpi/cpu_rank.hpp"
#include "mpi/device_choice.hpp"
#include "physics/rigid_body.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <regex>
#include <tuple>

namespace tridem::mpi {

namespace {

/// The particles `ids` of `m`, in that order: the model of one rank's copy of the scene.
ParticleModel slice(const ParticleModel& m, const std::vector<std::int32_t>& ids) {
  ParticleModel out;
  auto take = [&](auto& to, const auto& from) {
    to.clear();
    to.reserve(ids.size());
    for (std::int32_t i : ids) to.push_back(from[static_cast<std::size_t>(i)]);
  };
  take(out.offsets, m.offsets);
  take(out.centroid, m.centroid);
  take(out.area, m.area);
  take(out.mass, m.mass);
  take(out.inertia, m.inertia);
  take(out.longest_edge, m.longest_edge);
  take(out.smallest_height, m.smallest_height);
  take(out.material, m.material);
  take(out.motion, m.motion);
  take(out.velocity, m.velocity);
  take(out.angular_velocity, m.angular_velocity);
  take(out.program, m.program);
  out.programs = m.programs;
  out.program_knots = m.program_knots;
  return out;  // the bodies: slice_bodies
}

/// An Alltoallv's counts and displacements (doubles), `per` doubles per item, from the
/// items sent to and received from each rank, and the items in buffer order.
struct ExchangeLayout {
  std::vector<int> send_counts, send_displs, recv_counts, recv_displs;
  std::vector<std::int32_t> send_all, recv_all;
};

ExchangeLayout exchange_layout(const std::vector<std::vector<std::int32_t>>& send,
                               const std::vector<std::vector<std::int32_t>>& recv, int per) {
  ExchangeLayout l;
  const std::size_t ranks = send.size();
  l.send_counts.assign(ranks, 0);
  l.send_displs.assign(ranks, 0);
  l.recv_counts.assign(ranks, 0);
  l.recv_displs.assign(ranks, 0);
  int sent = 0, received = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    l.send_counts[r] = per * static_cast<int>(send[r].size());
    l.recv_counts[r] = per * static_cast<int>(recv[r].size());
    l.send_displs[r] = sent;
    l.recv_displs[r] = received;
    sent += l.send_counts[r];
    received += l.recv_counts[r];
    l.send_all.insert(l.send_all.end(), send[r].begin(), send[r].end());
    l.recv_all.insert(l.recv_all.end(), recv[r].begin(), recv[r].end());
  }
  return l;
}

/// The bodies of `m` whose members are `ids` (ascending, each body whole): a rank's
/// BodyModel, and each local body's global body in `bodies`.
BodyModel slice_bodies(const BodyModel& m, const std::vector<std::int32_t>& ids,
                       std::vector<std::int32_t>& bodies) {
  BodyModel out;
  bodies.clear();
  if (m.empty()) return out;
  out.first.push_back(0);
  for (std::size_t k = 0; k < ids.size();) {
    const auto gb = static_cast<std::size_t>(m.body[static_cast<std::size_t>(ids[k])]);
    const auto count = static_cast<std::size_t>(m.first[gb + 1] - m.first[gb]);
    if (ids[k] != m.first[gb] || k + count > ids.size() ||
        ids[k + count - 1] != m.first[gb + 1] - 1)
      throw RunError(fmt::format("internal error: rank holds body {} in part", gb));
    const auto lb = static_cast<std::int32_t>(bodies.size());
    bodies.push_back(static_cast<std::int32_t>(gb));
    out.centroid.push_back(m.centroid[gb]);
    out.mass.push_back(m.mass[gb]);
    out.inertia.push_back(m.inertia[gb]);
    out.half_size.push_back(m.half_size[gb]);
    out.motion.push_back(m.motion[gb]);
    out.velocity.push_back(m.velocity[gb]);
    out.angular_velocity.push_back(m.angular_velocity[gb]);
    out.program.push_back(m.program[gb]);
    for (std::size_t j = 0; j < count; ++j) {
      out.body.push_back(lb);
      out.member_offset.push_back(m.member_offset[static_cast<std::size_t>(ids[k + j])]);
    }
    k += count;
    out.first.push_back(static_cast<std::int64_t>(k));
  }
  return out;
}

/// Doubles of a contact record in a gather: i, j, force, point, normal, sliding, depth,
/// the partner image's translation.
constexpr std::size_t kContactDoubles = 12;

/// Each wall's load from its pairs' rows (wall, 0 = as emitter | 1 = as partner, other,
/// fx, fy, torque; six doubles each, any order): out(wall, force, torque) in Real as
/// sum_pair_forces adds it, its own row then the rows it is the partner of, each ascending.
template <class Real, class Out>
void sum_wall_loads(std::vector<double>& rows, Out&& out) {
  const std::size_t count = rows.size() / 6;
  std::vector<std::size_t> order(count);
  for (std::size_t r = 0; r < count; ++r) order[r] = r;
  auto key = [&](std::size_t r) {
    return std::tuple(as_id(rows[6 * r]), as_id(rows[6 * r + 1]), as_id(rows[6 * r + 2]));
  };
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  for (std::size_t a = 0; a < count;) {
    const std::int32_t w = as_id(rows[6 * order[a]]);
    Vec2<Real> f{};
    Real t = Real(0);
    for (; a < count && as_id(rows[6 * order[a]]) == w; ++a) {
      const double* l = &rows[6 * order[a]];
      const Vec2<Real> fa{static_cast<Real>(l[3]), static_cast<Real>(l[4])};
      if (l[1] == 0)
        f += fa;
      else
        f -= fa;
      t += static_cast<Real>(l[5]);
    }
    out(w, f, t);
  }
}

bool moving_wall_body(const BodyModel& m) {
  for (std::size_t b = 0; b < m.size(); ++b)
    if (m.motion[b] == Motion::Prescribed && m.first[b + 1] - m.first[b] > 1) return true;
  return false;
}

bool is_servo(const MotionProgram& p) { return p.kind == ProgramKind::Servo; }

bool has_servo(const ParticleModel& m) {
  return std::any_of(m.programs.begin(), m.programs.end(), is_servo);
}

}  // namespace

namespace {

/// What the ranks cannot split, as a phrase ("... on GPU ranks"), or nullptr.
const char* unsplit(const Scene& scene, const ParticleModel& model) {
  if (!model.bodies.empty() && has_servo(model))
    // A body's program reads the body's load, gathered from its members before the
    // check where the ranks sum a servo's load.
    return "servo walls in a scene with bodies of several triangles";
  if (moving_wall_body(model.bodies))
    return "moving wall bodies of several triangles (their load in bodies.csv is summed "
           "from their members at the step's start poses)";
  if (scene.simulation.method == Method::AllPairs)
    return "method = \"all-pairs\" (every wall emits its pairs there, across every strip)";
  return nullptr;
}

}  // namespace

std::string refusal(const Scene& scene, const ParticleModel& model, Backend ranks) {
  const bool gpu = ranks == Backend::Cuda;
  const char* what = unsplit(scene, model);
  if (!what && gpu)
    // A GPU rank's list in a periodic cell needs the cell one GPU needs (make_solver
    // checks it for one rank).
    return gpu_periodic_limit(scene, model).refusal;
  if (!what) return {};
  return fmt::format("{}: {} are not split across MPI ranks yet (docs/scaling.md); run "
                     "this scene on one rank (without mpirun, or mpirun -np 1)",
                     scene.source.empty() ? std::string("scene") : scene.source, what);
}

std::string gpu_ranks_decline(const Scene& scene, const ParticleModel& model) {
  if (const char* what = unsplit(scene, model))
    return fmt::format("{} are not split across MPI ranks yet", what);
  // GPU ranks run what CPU ranks split, in a periodic cell as long as one GPU needs.
  return gpu_periodic_limit(scene, model).reason;
}

template <class Real>
MpiSolver<Real>::MpiSolver(MPI_Comm comm, const Scene& scene, const ParticleModel& model,
                           const TimeStep& ts, const std::atomic<int>* os_interrupt,
                           std::atomic<int>* agreed_interrupt)
    : comm_(comm),
      scene_(scene),
      model_(model),
      ts_(ts),
      n_(model.size()),
      os_interrupt_(os_interrupt),
      agreed_interrupt_(agreed_interrupt) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  // The first collective: a rank that failed before (reading the scene) takes part in it
  // from mpi_run.cpp, so that every rank stops with that rank's message.
  std::string why = refusal(scene, model);
  // GPU ranks: each on the GPU its rank on the node picks; a rank without one refuses.
  gpu_ = scene.simulation.backend == Backend::Cuda;
  if (scene.simulation.backend == Backend::Auto && why.empty())
    gpu_ = auto_takes_gpus(scene, model);
  if (gpu_) {
    const int local_rank = node_local_rank(comm_);
    std::string reason;
    const int devices = cuda_available(&reason) ? cuda_device_count() : 0;
    if (why.empty()) why = gpu_rank_refusal(scene.source, rank_, devices, reason);
    device_ = device_for_rank(local_rank, devices);
  }
  if (auto m = agree(comm_, why.empty() ? std::nullopt : std::optional<std::string>(why)))
    throw SceneError(*m);
  if (gpu_) {
    devices_.assign(static_cast<std::size_t>(ranks_), 0);
    MPI_Gather(&device_, 1, MPI_INT, devices_.data(), 1, MPI_INT, 0, comm_);
  }

  radius_.resize(n_);
  double largest = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    double r = 0;
    for (const Vec2d& v : model_.offsets[i]) r = std::max(r, std::hypot(v.x, v.y));
    radius_[i] = r;
    if (model_.motion[i] == Motion::Free) largest = std::max(largest, r);
  }
  // A skin of one particle radius: the plan lasts until something moves half of it.
  skin_ = largest;
  // What a rank's solver reads of the scene: its settings and materials, and its own
  // bonds (build_local); not the scene's triangles.
  rank_scene_ = scene_;
  rank_scene_.triangles.clear();
  rank_scene_.triangles.shrink_to_fit();
  rank_scene_.bonds.clear();
  servo_ = servo_wall_mask(model_);

  char version[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  MPI_Get_library_version(version, &length);
  library_ = std::string(version, static_cast<std::size_t>(length));
  library_ = library_.substr(0, library_.find_first_of(",\n"));
  measure_bandwidth();

  // The scene's initial state as a whole state, and the first plan from it.
  SolverState whole;
  SolverState::for_each_field([&](auto field) {
    for_each_array(whole.column(field), [&](std::vector<double>& v, int k) {
      v = initial_column<double>(field, model_, k);
    });
  });
  if (!model_.bodies.empty())
    SolverState::for_each_body_column([&](auto field) {
      whole.column(field) = initial_body_column(field, model_.bodies, model_.bodies.size());
    });
  // Bonds start intact, having released nothing.
  whole.bond_damage.assign(SolverState::kBondStatePoints * scene_.bonds.size(), 0.0);
  whole.bond_dissipated.assign(scene_.bonds.size(), 0.0);
  decompose(whole);
}

template <class Real>
bool MpiSolver<Real>::auto_takes_gpus(const Scene& scene, const ParticleModel& model) const {
  // GPU ranks when every rank has a GPU and GPU ranks run the scene; CPU ranks otherwise,
  // saying why where GPUs were there to take.
  const int has_gpu = cuda_available() && cuda_device_count() > 0 ? 1 : 0;
  int every = 0;
  MPI_Allreduce(&has_gpu, &every, 1, MPI_INT, MPI_MIN, comm_);
  if (every == 0) return false;
  const std::string why = gpu_ranks_decline(scene, model);
  if (why.empty()) return true;
  if (rank_ == 0)
    fmt::print(stderr, "note: backend = auto runs CPU ranks, not GPU ranks: {}\n", why);
  return false;
}

template <class Real>
MpiSolver<Real>::~MpiSolver() {
  if (rank_ == 0) order(std::uncaught_exceptions() > 0 ? kAbort : kStop, 0);
}

template <class Real>
void MpiSolver<Real>::order(Command c, long long arg) const {
  long long command[2] = {c, arg};
  MPI_Bcast(command, 2, MPI_LONG_LONG, 0, comm_);
}

template <class Real>
bool MpiSolver<Real>::serve() {
  SolverState whole;
  for (;;) {
    long long command[2] = {0, 0};
    MPI_Bcast(command, 2, MPI_LONG_LONG, 0, comm_);
    try {
      switch (command[0]) {
        case kAdvance: run_steps(command[1]); break;
        case kSnapshot: gather_snapshot(nullptr, command[1] != 0); break;
        case kSave: gather_state(whole); break;
        case kCheckpoint: write_checkpoint_part(nullptr, nullptr); break;
        case kLoad:
          broadcast_state(whole);
          decompose(whole);
          break;
        case kEnergy: gather_energy(); break;
        case kStop: return true;
        default: return false;
      }
    } catch (const RunError&) {
      // Agreed by every rank: rank 0 reports it and goes on (last_good.ckpt).
    }
  }
}

template <class Real>
void MpiSolver<Real>::advance(std::int64_t steps) {
  order(kAdvance, steps);
  run_steps(steps);
}

template <class Real>
void MpiSolver<Real>::run_steps(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) step_once();
  // Between advances the ghosts are their owners' (snapshots, states, a new plan).
  finish_exchange();
}

template <class Real>
void MpiSolver<Real>::step_once() {
  if (redecompose_) {
    finish_exchange();  // its buffers belong to the local solver the plan replaces
    SolverState whole;
    gather_state(whole);
    decompose(whole);
    redecompose_ = false;
  }
  check_agreed_ = false;
  try {
    local_->solver().advance(1);
  } catch (const std::exception& e) {
    // Every rank started the exchange: each completes it (the others may be waiting on it).
    finish_exchange();
    // This rank failed before or in its Check: tell the others, which are waiting in
    // their check hook. When the hook threw, the agreement is already made.
    if (!check_agreed_) agreed_ = agree(comm_, global_ids(e.what())).value_or(e.what());
    throw RunError(agreed_);
  }
  if (overlap_)
    start_exchange();
  else
    exchange_ghosts();
  int mine[2] = {os_interrupt_ ? os_interrupt_->load() : 0, drifted() ? 1 : 0};
  int all[2] = {0, 0};
  MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, comm_);
  if (all[0] != 0 && agreed_interrupt_) agreed_interrupt_->store(all[0]);
  redecompose_ = all[1] != 0;
}

template <class Real>
void MpiSolver<Real>::exchange_ghosts() {
  start_exchange();
  finish_exchange();
}

template <class Real>
void MpiSolver<Real>::start_exchange() {
  local_->pack();
  MPI_Ialltoallv(local_->send_buffer(), send_counts_.data(), send_displs_.data(), MPI_DOUBLE,
                 local_->receive_buffer(), recv_counts_.data(), recv_displs_.data(), MPI_DOUBLE,
                 comm_, &requests_[0]);
  if (!model_.bodies.empty())  // on every rank, even one that holds none
    MPI_Ialltoallv(local_->body_send_buffer(), body_send_counts_.data(), body_send_displs_.data(),
                   MPI_DOUBLE, local_->body_receive_buffer(), body_recv_counts_.data(),
                   body_recv_displs_.data(), MPI_DOUBLE, comm_, &requests_[1]);
  in_flight_ = true;
}

template <class Real>
void MpiSolver<Real>::finish_exchange() {
  if (!in_flight_) return;
  const auto start = std::chrono::steady_clock::now();
  MPI_Waitall(2, requests_, MPI_STATUSES_IGNORE);
  exchange_wait_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  in_flight_ = false;
  local_->unpack();
}

template <class Real>
void MpiSolver<Real>::poll_exchange() {
  // Without a progress thread, MPI moves a large message only inside MPI calls.
  int done = 0;
  if (in_flight_) MPI_Testall(2, requests_, &done, MPI_STATUSES_IGNORE);
}

template <class Real>
bool MpiSolver<Real>::drifted() const {
  return local_->drifted(0.5 * skin_);  // half the skin
}

template <class Real>
int MpiSolver<Real>::authority(std::int32_t a, std::int32_t b) const {
  // The owner of the emitter's row, else of the partner (a wall that emits nothing is the
  // partner of a grain); two walls are never a pair.
  const int oa = plan_.owner[static_cast<std::size_t>(a)];
  if (oa >= 0) return oa;
  return std::max(0, plan_.owner[static_cast<std::size_t>(b)]);
}

template <class Real>
typename MpiSolver<Real>::Reported MpiSolver<Real>::reported(const SolverState& ls) const {
  Reported own;
  for (std::size_t k = 0; k < global_.size(); ++k)
    if (reports(global_[k])) own.particles.push_back(k);
  for (std::size_t p = 0; p < ls.pairs(); ++p)
    if (authority(global_[static_cast<std::size_t>(ls.pair_emitter[p])],
                  global_[static_cast<std::size_t>(ls.pair_partner[p])]) == rank_)
      own.pairs.push_back(p);
  for (std::size_t b = 0; b < global_body_.size(); ++b)
    if (reports_body(b)) own.bodies.push_back(b);
  for (std::size_t k = 0; k < global_bond_.size(); ++k)
    if (reports_bond(static_cast<std::size_t>(global_bond_[k]))) own.bonds.push_back(k);
  return own;
}

template <class Real>
void MpiSolver<Real>::pack_particle(std::vector<double>& to, const SolverState& ls,
                                    std::size_t k) const {
  to.push_back(global_[k]);
  SolverState::for_each_field([&](auto field) {
    for_each_array(ls.column(field), [&](const std::vector<double>& v, int) {
      to.push_back(v.empty() ? 0.0 : v[k]);
    });
  });
}

template <class Real>
void MpiSolver<Real>::pack_pair(std::vector<double>& to, const SolverState& ls,
                                std::size_t p) const {
  to.push_back(global_[static_cast<std::size_t>(ls.pair_emitter[p])]);
  to.push_back(global_[static_cast<std::size_t>(ls.pair_partner[p])]);
  for (double s : ls.pair_slip[p]) to.push_back(s);
}

template <class Real>
void MpiSolver<Real>::pack_body(std::vector<double>& to, const SolverState& ls,
                                std::size_t b) const {
  to.push_back(global_body_[b]);
  SolverState::for_each_body_column([&](auto field) { to.push_back(ls.column(field)[b]); });
}

template <class Real>
void MpiSolver<Real>::pack_bond(std::vector<double>& to, const SolverState& ls,
                                std::size_t k) const {
  constexpr std::size_t kPoints = SolverState::kBondStatePoints;
  to.push_back(global_bond_[k]);
  for (std::size_t q = 0; q < kPoints; ++q) to.push_back(ls.bond_damage[kPoints * k + q]);
  to.push_back(ls.bond_dissipated[k]);
}

template <class Real>
typename MpiSolver<Real>::PairRecord MpiSolver<Real>::read_pair(const std::vector<double>& from,
                                                                std::size_t& at) {
  PairRecord r{as_id(from[at]), as_id(from[at + 1]), {}};
  at += 2;
  for (double& s : std::get<2>(r)) s = from[at++];
  return r;
}

template <class Real>
void MpiSolver<Real>::append_sorted(std::vector<PairRecord>& pairs, SolverState& out) {
  std::sort(pairs.begin(), pairs.end(), [](const PairRecord& a, const PairRecord& b) {
    return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
  });
  for (const auto& [e, j, slip] : pairs) {
    out.pair_emitter.push_back(e);
    out.pair_partner.push_back(j);
    out.pair_slip.push_back(slip);
  }
}

template <class Real>
void MpiSolver<Real>::gather_state(SolverState& out) const {
  SolverState& ls = scratch_state_;
  local_->solver().save_state(ls);
  const Reported own = reported(ls);
  std::vector<double> mine;
  mine.push_back(static_cast<double>(own.particles.size()));
  mine.push_back(static_cast<double>(own.pairs.size()));
  mine.push_back(static_cast<double>(own.bodies.size()));
  mine.push_back(static_cast<double>(own.bonds.size()));
  for (std::size_t k : own.particles) pack_particle(mine, ls, k);
  for (std::size_t p : own.pairs) pack_pair(mine, ls, p);
  for (std::size_t b : own.bodies) pack_body(mine, ls, b);
  for (std::size_t k : own.bonds) pack_bond(mine, ls, k);
  const std::vector<double> all = collect(comm_, mine, true);

  constexpr std::size_t kPoints = SolverState::kBondStatePoints;
  out = SolverState{};
  out.step = ls.step;
  out.time = ls.time;
  SolverState::for_each_field([&](auto field) {
    for_each_array(out.column(field), [&](std::vector<double>& v, int) { v.assign(n_, 0.0); });
  });
  SolverState::for_each_body_column(
      [&](auto field) { out.column(field).assign(model_.bodies.size(), 0.0); });
  out.bond_damage.assign(kPoints * scene_.bonds.size(), 0.0);
  out.bond_dissipated.assign(scene_.bonds.size(), 0.0);
  std::vector<PairRecord> history;
  std::size_t at = 0;
  while (at < all.size()) {
    const auto particles = static_cast<std::size_t>(all[at]),
               rank_pairs = static_cast<std::size_t>(all[at + 1]),
               rank_bodies = static_cast<std::size_t>(all[at + 2]),
               rank_bonds = static_cast<std::size_t>(all[at + 3]);
    at += 4;
    for (std::size_t q = 0; q < particles; ++q) {
      const auto g = static_cast<std::size_t>(all[at++]);
      SolverState::for_each_field([&](auto field) {
        for_each_array(out.column(field), [&](std::vector<double>& v, int) { v[g] = all[at++]; });
      });
    }
    for (std::size_t q = 0; q < rank_pairs; ++q) history.push_back(read_pair(all, at));
    for (std::size_t q = 0; q < rank_bodies; ++q) {
      const auto gb = static_cast<std::size_t>(all[at++]);
      SolverState::for_each_body_column([&](auto field) { out.column(field)[gb] = all[at++]; });
    }
    for (std::size_t q = 0; q < rank_bonds; ++q) {
      const auto gk = static_cast<std::size_t>(all[at++]);
      for (std::size_t p = 0; p < kPoints; ++p) out.bond_damage[kPoints * gk + p] = all[at++];
      out.bond_dissipated[gk] = all[at++];
    }
  }
  append_sorted(history, out);
}

template <class Real>
void MpiSolver<Real>::decompose(const SolverState& whole) {
  std::optional<std::string> problem;
  try {
    build_local(whole);
  } catch (const std::exception& e) {
    problem = global_ids(e.what());
  }
  if (auto m = agree(comm_, problem)) throw RunError(*m);
}

template <class Real>
void MpiSolver<Real>::build_local(const SolverState& whole) {
  StripInput in;
  in.x = whole.x;
  in.y = whole.y;
  in.motion = model_.motion;
  in.radius = radius_;
  in.longest_edge = model_.longest_edge;
  in.contacts.assign(n_, 0);
  for (std::size_t p = 0; p < whole.pairs(); ++p) {
    ++in.contacts[static_cast<std::size_t>(whole.pair_emitter[p])];
    ++in.contacts[static_cast<std::size_t>(whole.pair_partner[p])];
  }
  in.ranks = ranks_;
  in.skin = skin_;
  const PeriodicCell& cell = scene_.simulation.periodic;
  for (const auto& [axis, range] : {std::pair{0, cell.x}, std::pair{1, cell.y}})
    if (range) {
      in.periodic[axis] = true;
      in.period[axis] = range->length();
    }
  in.sheared = cell.shear_rate != 0;
  for (const BondSpec& b : scene_.bonds)
    in.bonds.push_back({static_cast<std::int32_t>(b.a), static_cast<std::int32_t>(b.b)});
  // A free body's members go together; a wall body's are walls, held everywhere.
  const BodyModel& bm = model_.bodies;
  if (!bm.empty()) {
    in.unit.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const auto b = static_cast<std::size_t>(bm.body[i]);
      in.unit[i] = bm.motion[b] == Motion::Free ? static_cast<std::int32_t>(bm.first[b])
                                                : static_cast<std::int32_t>(i);
    }
  }
  plan_ = plan_strips(in);
  global_ = plan_.held[static_cast<std::size_t>(rank_)];
  local_of_.assign(n_, -1);
  for (std::size_t k = 0; k < global_.size(); ++k)
    local_of_[static_cast<std::size_t>(global_[k])] = static_cast<std::int32_t>(k);

  if (local_) {
    earlier_overlap_ += local_->overlap_counts();
    const StageTimes t = local_->solver().stage_times();
    for (int s = 0; s < kStageCount; ++s) earlier_times_.seconds[s] += t.seconds[s];
    earlier_times_.steps += t.steps;
    earlier_times_.timed_steps += t.timed_steps;
  }
  SolverConfig config;
  config.force = true;  // the whole scene's time step was checked by the run
  // The bonds between particles this rank holds, in the scene's order.
  rank_scene_.bonds.clear();
  global_bond_.clear();
  for (std::size_t k = 0; k < scene_.bonds.size(); ++k) {
    BondSpec b = scene_.bonds[k];
    const std::int32_t la = local_of_[b.a], lb = local_of_[b.b];
    if (la < 0 || lb < 0) continue;
    b.a = static_cast<std::size_t>(la);
    b.b = static_cast<std::size_t>(lb);
    rank_scene_.bonds.push_back(b);
    global_bond_.push_back(static_cast<std::int32_t>(k));
  }
  ParticleModel local_model = slice(model_, global_);
  local_model.bodies = slice_bodies(model_.bodies, global_, global_body_);
  if (gpu_) {
    config.device = device_;
    local_.reset();  // its GPU memory first
    local_ = make_cuda_rank<Real>(rank_scene_, local_model, ts_, config);
  } else {
    local_ = std::make_unique<CpuRank<Real>>(rank_scene_, local_model, ts_, config);
  }
  local_->solver().set_stage_timing(timing_);
  local_->set_check_hook([this] {
    check_agreed_ = true;
    if (auto m = agree(comm_, std::nullopt)) {
      agreed_ = *m;
      throw RunError(agreed_);
    }
    if (!servo_.empty()) sum_servo_loads();
  });

  SolverState ls;
  ls.step = whole.step;
  ls.time = whole.time;
  SolverState::for_each_field([&](auto field) {
    for_each_array(ls.column(field), [&](std::vector<double>& v, int k) {
      const std::vector<double>& from = array_at(whole.column(field), k);
      v.resize(global_.size());
      for (std::size_t q = 0; q < global_.size(); ++q)
        v[q] = from.empty() ? 0.0 : from[static_cast<std::size_t>(global_[q])];
    });
  });
  SolverState::for_each_body_column([&](auto field) {
    const std::vector<double>& from = whole.column(field);
    std::vector<double>& v = ls.column(field);
    v.resize(global_body_.size());
    for (std::size_t b = 0; b < global_body_.size(); ++b)
      v[b] = from[static_cast<std::size_t>(global_body_[b])];
  });
  if (!whole.bond_dissipated.empty()) {
    constexpr std::size_t kPoints = SolverState::kBondStatePoints;
    for (const std::int32_t gk : global_bond_) {
      const auto k = static_cast<std::size_t>(gk);
      ls.bond_damage.insert(ls.bond_damage.end(), whole.bond_damage.begin() + kPoints * k,
                            whole.bond_damage.begin() + kPoints * (k + 1));
      ls.bond_dissipated.push_back(whole.bond_dissipated[k]);
    }
  }
  // Global ids keep their order in the local numbering: the history stays sorted.
  for (std::size_t p = 0; p < whole.pairs(); ++p) {
    const std::int32_t e = local_of_[static_cast<std::size_t>(whole.pair_emitter[p])];
    const std::int32_t j = local_of_[static_cast<std::size_t>(whole.pair_partner[p])];
    if (e < 0 || j < 0) continue;
    ls.pair_emitter.push_back(e);
    ls.pair_partner.push_back(j);
    ls.pair_slip.push_back(whole.pair_slip[p]);
  }
  local_->solver().load_state(ls);

  const auto ranks = static_cast<std::size_t>(ranks_);
  std::vector<std::vector<std::int32_t>> send(ranks), recv(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    if (static_cast<int>(r) == rank_) continue;
    for (std::int32_t g : plan_.held[r])
      if (plan_.owns(rank_, g) && model_.motion[static_cast<std::size_t>(g)] == Motion::Free)
        send[r].push_back(local_of_[static_cast<std::size_t>(g)]);
  }
  // Walls are stepped by every rank: only grains are sent.
  std::vector<std::int32_t> own;
  for (std::size_t k = 0; k < global_.size(); ++k) {
    const auto g = static_cast<std::size_t>(global_[k]);
    const int owner = plan_.owner[g];
    if (owner >= 0 && owner != rank_ && model_.motion[g] == Motion::Free)
      recv[static_cast<std::size_t>(owner)].push_back(static_cast<std::int32_t>(k));
    if (owner == rank_) own.push_back(static_cast<std::int32_t>(k));
  }
  ExchangeLayout l = exchange_layout(send, recv, state_array_count());
  send_counts_ = std::move(l.send_counts);
  send_displs_ = std::move(l.send_displs);
  recv_counts_ = std::move(l.recv_counts);
  recv_displs_ = std::move(l.recv_displs);
  const std::vector<std::int32_t>& send_all = l.send_all;
  const std::vector<std::int32_t>& recv_all = l.recv_all;
  local_->set_plan(send_all, recv_all, own);
  // A free body's State goes with its members: from the owner of its first member to the
  // ranks that hold it.
  std::vector<std::vector<std::int32_t>> body_send(ranks), body_recv(ranks);
  for (std::size_t lb = 0; lb < global_body_.size(); ++lb) {
    const auto gb = static_cast<std::size_t>(global_body_[lb]);
    if (bm.motion[gb] != Motion::Free) continue;
    const auto head = static_cast<std::int32_t>(bm.first[gb]);
    const int owner = plan_.owner[static_cast<std::size_t>(head)];
    if (owner != rank_) {
      body_recv[static_cast<std::size_t>(owner)].push_back(static_cast<std::int32_t>(lb));
      continue;
    }
    for (std::size_t r = 0; r < ranks; ++r) {
      const auto& h = plan_.held[r];
      if (static_cast<int>(r) != rank_ && std::binary_search(h.begin(), h.end(), head))
        body_send[r].push_back(static_cast<std::int32_t>(lb));
    }
  }
  ExchangeLayout b = exchange_layout(body_send, body_recv, RankSolver<Real>::kBodyStateArrays);
  body_send_counts_ = std::move(b.send_counts);
  body_send_displs_ = std::move(b.send_displs);
  body_recv_counts_ = std::move(b.recv_counts);
  body_recv_displs_ = std::move(b.recv_displs);
  local_->set_body_plan(b.send_all, b.recv_all);
  overlap_ =
      local_->take_ghosts_mid_step([this] { finish_exchange(); }, [this] { poll_exchange(); });
  ++plans_;
}

template <class Real>
void MpiSolver<Real>::gather_snapshot(Snapshot* out, bool with_contacts) const {
  Snapshot& ls = scratch_snapshot_;
  local_->solver().snapshot(ls, with_contacts);
  std::vector<double> rows, loads, contacts;
  for (std::size_t k = 0; k < global_.size(); ++k) {
    const auto g = static_cast<std::size_t>(global_[k]);
    if (!reports(global_[k])) continue;
    rows.push_back(static_cast<double>(g));
    Snapshot::for_each_field([&](auto field) {
      for_each_array(ls.column(field),
                     [&](const std::vector<double>& v, int) { rows.push_back(v[k]); });
    });
    for (const auto* v : {&ls.x1, &ls.y1, &ls.x2, &ls.y2, &ls.x3, &ls.y3, &ls.mass, &ls.inertia})
      rows.push_back((*v)[k]);
    rows.push_back(ls.material[k]);
    rows.push_back(static_cast<double>(static_cast<int>(ls.motion[k])));
  }
  // The walls' loads, pair by pair, summed on rank 0 in sum_pair_forces' order.
  loads = wall_pair_loads(
      [&](const auto& f) { for_each_last_pair(f); },
      [&](std::int32_t g) { return model_.motion[static_cast<std::size_t>(g)] != Motion::Free; });
  for (const ContactRecord& c : ls.contacts) {
    const std::int32_t gi = global_[static_cast<std::size_t>(c.i)];
    const std::int32_t gj = global_[static_cast<std::size_t>(c.j)];
    if (authority(gi, gj) != rank_) continue;
    contacts.insert(contacts.end(), {double(gi), double(gj), c.fx, c.fy, c.px, c.py, c.nx, c.ny,
                                     c.sliding ? 1.0 : 0.0, c.depth, c.image_dx, c.image_dy});
  }
  std::vector<double> bond_rows;
  for (std::size_t k = 0; k < global_bond_.size(); ++k) {
    if (!reports_bond(static_cast<std::size_t>(global_bond_[k]))) continue;
    bond_rows.insert(bond_rows.end(),
                     {double(global_bond_[k]), double(ls.bond_broken[k]), ls.bond_damage[k],
                      ls.bond_x0[k], ls.bond_y0[k], ls.bond_x1[k], ls.bond_y1[k]});
  }
  std::vector<double> body_rows;
  for (std::size_t b = 0; b < global_body_.size(); ++b) {
    if (!reports_body(b)) continue;
    body_rows.push_back(global_body_[b]);
    Snapshot::for_each_body_column([&](auto field) { body_rows.push_back(ls.column(field)[b]); });
  }
  std::vector<double> mine;
  mine.push_back(static_cast<double>(rows.size()));
  mine.push_back(static_cast<double>(loads.size()));
  mine.push_back(static_cast<double>(contacts.size()));
  mine.push_back(static_cast<double>(body_rows.size()));
  mine.push_back(static_cast<double>(bond_rows.size()));
  for (const auto* v : {&rows, &loads, &contacts, &body_rows, &bond_rows})
    mine.insert(mine.end(), v->begin(), v->end());
  const std::vector<double> all = collect(comm_, mine, false);
  if (rank_ != 0 || !out) return;

  Snapshot& s = *out;
  s.step = ls.step;
  s.time = ls.time;
  s.resize(n_);
  s.resize_bodies(model_.bodies.size());
  if (!model_.bodies.empty()) {
    // What the snapshot derives from the bodies' model, as snapshot_fill does.
    const BodyModel& m = model_.bodies;
    const std::size_t nb = m.size();
    s.member_body = m.body;
    const auto inv_mass = initial_body_column(body_field::body_inv_mass{}, m, nb);
    const auto inv_inertia = initial_body_column(body_field::body_inv_inertia{}, m, nb);
    for (std::size_t b = 0; b < nb; ++b) {
      s.body_mass[b] = inv_mass[b] > 0 ? 1.0 / inv_mass[b] : 0.0;
      s.body_inertia[b] = inv_inertia[b] > 0 ? 1.0 / inv_inertia[b] : 0.0;
      s.body_first[b] = m.first[b];
    }
    s.body_first[nb] = m.first[nb];
  }
  s.contacts.clear();
  s.contact_precision = kPrecisionOf<Real>;
  const std::size_t n_bonds = scene_.bonds.size();
  s.bond_a.resize(n_bonds);
  s.bond_b.resize(n_bonds);
  for (std::size_t k = 0; k < n_bonds; ++k) {
    s.bond_a[k] = static_cast<std::int32_t>(scene_.bonds[k].a);
    s.bond_b[k] = static_cast<std::int32_t>(scene_.bonds[k].b);
  }
  s.bond_broken.assign(n_bonds, 0);
  for (auto* v : {&s.bond_damage, &s.bond_x0, &s.bond_y0, &s.bond_x1, &s.bond_y1})
    v->assign(n_bonds, 0.0);
  std::vector<double> wall_loads;
  std::size_t at = 0;
  while (at < all.size()) {
    const auto nr = static_cast<std::size_t>(all[at]), nl = static_cast<std::size_t>(all[at + 1]),
               nc = static_cast<std::size_t>(all[at + 2]),
               nb = static_cast<std::size_t>(all[at + 3]),
               nk = static_cast<std::size_t>(all[at + 4]);
    at += 5;
    for (const std::size_t end = at + nr; at < end;) {
      const auto g = static_cast<std::size_t>(all[at++]);
      Snapshot::for_each_field([&](auto field) {
        for_each_array(s.column(field), [&](std::vector<double>& v, int) { v[g] = all[at++]; });
      });
      for (auto* v : {&s.x1, &s.y1, &s.x2, &s.y2, &s.x3, &s.y3, &s.mass, &s.inertia})
        (*v)[g] = all[at++];
      s.material[g] = static_cast<int>(all[at++]);
      s.motion[g] = static_cast<Motion>(static_cast<int>(all[at++]));
    }
    wall_loads.insert(wall_loads.end(), all.begin() + static_cast<std::ptrdiff_t>(at),
                      all.begin() + static_cast<std::ptrdiff_t>(at + nl));
    at += nl;
    for (const std::size_t end = at + nc; at < end; at += kContactDoubles) {
      ContactRecord c;
      c.i = as_id(all[at]);
      c.j = as_id(all[at + 1]);
      c.fx = all[at + 2];
      c.fy = all[at + 3];
      c.px = all[at + 4];
      c.py = all[at + 5];
      c.nx = all[at + 6];
      c.ny = all[at + 7];
      c.sliding = all[at + 8] != 0;
      c.depth = all[at + 9];
      c.image_dx = all[at + 10];
      c.image_dy = all[at + 11];
      s.contacts.push_back(c);
    }
    for (const std::size_t end = at + nb; at < end;) {
      const auto gb = static_cast<std::size_t>(all[at++]);
      Snapshot::for_each_body_column([&](auto field) { s.column(field)[gb] = all[at++]; });
    }
    for (const std::size_t end = at + nk; at < end; at += 7) {
      const auto k = static_cast<std::size_t>(all[at]);
      s.bond_broken[k] = static_cast<std::uint8_t>(all[at + 1]);
      s.bond_damage[k] = all[at + 2];
      s.bond_x0[k] = all[at + 3];
      s.bond_y0[k] = all[at + 4];
      s.bond_x1[k] = all[at + 5];
      s.bond_y1[k] = all[at + 6];
    }
  }
  std::sort(s.contacts.begin(), s.contacts.end(),
            [](const ContactRecord& a, const ContactRecord& b) {
              return std::tie(a.i, a.j) < std::tie(b.i, b.j);
            });
  if (step() == 0) return;
  // A wall no pair reaches has +0.
  for (std::size_t i = 0; i < n_; ++i)
    if (model_.motion[i] != Motion::Free) s.fx[i] = s.fy[i] = s.torque[i] = 0;
  sum_wall_loads<Real>(wall_loads, [&](std::int32_t w, Vec2<Real> f, Real t) {
    s.fx[static_cast<std::size_t>(w)] = static_cast<double>(f.x);
    s.fy[static_cast<std::size_t>(w)] = static_cast<double>(f.y);
    s.torque[static_cast<std::size_t>(w)] = static_cast<double>(t);
  });
  // A wall body's load from its members', as gather_bodies sums it (its members' arms at
  // the step's start: the poses now for a wall body that does not move, refusal() keeps
  // the others to one member, whose arm is zero).
  const BodyModel& bm = model_.bodies;
  for (std::size_t b = 0; b < bm.size(); ++b) {
    if (bm.motion[b] == Motion::Free) continue;
    Vec2d f{};
    double t = 0;
    for (auto i = static_cast<std::size_t>(bm.first[b]);
         i < static_cast<std::size_t>(bm.first[b + 1]); ++i)
      physics::add_member_load(
          f, t, Vec2<Real>{static_cast<Real>(s.fx[i]), static_cast<Real>(s.fy[i])},
          static_cast<Real>(s.torque[i]), Vec2d{s.x[i] - s.body_x[b], s.y[i] - s.body_y[b]});
    s.body_fx[b] = f.x;
    s.body_fy[b] = f.y;
    s.body_torque[b] = t;
  }
}

template <class Real>
template <class Visit, class IsWall>
std::vector<double> MpiSolver<Real>::wall_pair_loads(Visit&& visit_pairs, IsWall&& is_wall) const {
  std::vector<double> loads;
  visit_pairs([&](std::int32_t ge, std::int32_t gj, const physics::PairForce<Real>& f) {
    const bool we = is_wall(ge), wj = is_wall(gj);
    if (!(we || wj) || authority(ge, gj) != rank_) return;
    if (we)
      loads.insert(loads.end(), {double(ge), 0.0, double(gj), double(f.force_a.x),
                                 double(f.force_a.y), double(f.torque_a)});
    if (wj)
      loads.insert(loads.end(), {double(gj), 1.0, double(ge), double(f.force_a.x),
                                 double(f.force_a.y), double(f.torque_b)});
  });
  return loads;
}

template <class Real>
void MpiSolver<Real>::sum_servo_loads() {
  const std::vector<double> mine = wall_pair_loads(
      [&](const auto& f) {
        local_->for_each_step_pair(
            [&](std::int32_t e, std::int32_t j, const physics::PairForce<Real>& force) {
              f(global_[static_cast<std::size_t>(e)], global_[static_cast<std::size_t>(j)], force);
            });
      },
      [&](std::int32_t g) { return servo_[static_cast<std::size_t>(g)] != 0; });
  std::vector<double> all = collect(comm_, mine, true);
  // Every rank holds a servo wall that is not owned (large walls are everyone's); an owned
  // one only where its strip is. A wall no pair reaches keeps the +0 its gather gave it.
  sum_wall_loads<Real>(all, [&](std::int32_t w, Vec2<Real> f, Real t) {
    const std::int32_t local = local_of_[static_cast<std::size_t>(w)];
    if (local >= 0) local_->set_load(local, f, t);
  });
}

template <class Real>
EnergyBudget MpiSolver<Real>::gather_energy() const {
  std::vector<double> energy;
  local_->energy_sums(energy);
  const std::size_t per = kEnergyAccumulators;
  std::vector<double> sums, elastic;
  for (std::size_t k = 0; k < global_.size(); ++k) {
    const auto g = static_cast<std::size_t>(global_[k]);
    if (!reports(global_[k])) continue;
    sums.push_back(static_cast<double>(g));
    for (std::size_t a = 0; a < per; ++a) sums.push_back(energy[k * per + a]);
  }
  // The terms the local backend adds (pairs on the CPU, rows on the GPU), by global ids; a
  // row (partner -1) is its emitter's owner's.
  local_->elastic_terms([&](std::int32_t e, std::int32_t j, double value) {
    const std::int32_t ge = global_[static_cast<std::size_t>(e)];
    const std::int32_t gj = j < 0 ? -1 : global_[static_cast<std::size_t>(j)];
    const int who = gj < 0 ? plan_.owner[static_cast<std::size_t>(ge)] : authority(ge, gj);
    if (value != 0 && who == rank_) elastic.insert(elastic.end(), {double(ge), double(gj), value});
  });
  // Each bond's elastic energy and the energy it released, from the authority of its pair.
  std::vector<double> bonds;
  if (!global_bond_.empty())
    local_->bond_terms([&](std::size_t k, double bond_elastic, double released) {
      const auto gk = static_cast<std::size_t>(global_bond_[k]);
      if (reports_bond(gk)) bonds.insert(bonds.end(), {double(gk), bond_elastic, released});
    });
  std::vector<double> mine{static_cast<double>(sums.size()), static_cast<double>(elastic.size()),
                           static_cast<double>(bonds.size())};
  mine.insert(mine.end(), sums.begin(), sums.end());
  mine.insert(mine.end(), elastic.begin(), elastic.end());
  mine.insert(mine.end(), bonds.begin(), bonds.end());
  const std::vector<double> all = collect(comm_, mine, false);
  EnergyBudget b;
  if (rank_ != 0) return b;
  std::vector<double> by_particle(n_ * per, 0.0);
  std::vector<std::tuple<std::int32_t, std::int32_t, double>> pairs;
  std::vector<double> bond_elastic(scene_.bonds.size(), 0.0), released(scene_.bonds.size(), 0.0);
  for (std::size_t at = 0; at < all.size();) {
    const auto ns = static_cast<std::size_t>(all[at]), ne = static_cast<std::size_t>(all[at + 1]),
               nk = static_cast<std::size_t>(all[at + 2]);
    at += 3;
    for (const std::size_t end = at + ns; at < end; at += 1 + per)
      for (std::size_t k = 0; k < per; ++k)
        by_particle[static_cast<std::size_t>(all[at]) * per + k] = all[at + 1 + k];
    for (const std::size_t end = at + ne; at < end; at += 3)
      pairs.emplace_back(as_id(all[at]), as_id(all[at + 1]), all[at + 2]);
    for (const std::size_t end = at + nk; at < end; at += 3) {
      bond_elastic[static_cast<std::size_t>(all[at])] = all[at + 1];
      released[static_cast<std::size_t>(all[at])] = all[at + 2];
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& p : pairs) b.elastic += std::get<2>(p);
  for (std::size_t i = 0; i < n_; ++i) {
    b.dissipated_damping += by_particle[i * per + kDissipatedDamping];
    b.dissipated_friction += by_particle[i * per + kDissipatedFriction];
    b.dissipated_local += by_particle[i * per + kDissipatedLocal];
    b.wall_work += by_particle[i * per + kWallWork];
  }
  // As CpuSolver::energy adds them: the bonds' elastic energy after the pairs', in order.
  for (const double e : bond_elastic) b.elastic += e;
  for (const double d : released) b.dissipated_fracture += d;
  return b;
}

template <class Real>
void MpiSolver<Real>::snapshot(Snapshot& out, bool with_contacts) const {
  order(kSnapshot, with_contacts ? 1 : 0);
  gather_snapshot(&out, with_contacts);
}

template <class Real>
void MpiSolver<Real>::save_state(SolverState& out) const {
  order(kSave, 0);
  gather_state(out);
}

template <class Real>
EnergyBudget MpiSolver<Real>::energy() const {
  order(kEnergy, 0);
  return gather_energy();
}

template <class Real>
void MpiSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, model_.bodies.size(), description());
  validate_bond_state(in, scene_.bonds.size(), description());
  order(kLoad, 0);
  SolverState whole = in;
  broadcast_state(whole);
  decompose(whole);
  redecompose_ = false;
}

template <class Real>
void MpiSolver<Real>::broadcast_state(SolverState& s) const {
  std::vector<double> data;
  if (rank_ == 0) {
    data.push_back(static_cast<double>(s.step));
    data.push_back(s.time);
    data.push_back(static_cast<double>(s.pairs()));
    SolverState::for_each_field([&](auto field) {
      for_each_array(s.column(field), [&](const std::vector<double>& v, int) {
        for (std::size_t i = 0; i < n_; ++i) data.push_back(v.empty() ? 0.0 : v[i]);
      });
    });
    for (std::size_t p = 0; p < s.pairs(); ++p) {
      data.push_back(s.pair_emitter[p]);
      data.push_back(s.pair_partner[p]);
      for (double v : s.pair_slip[p]) data.push_back(v);
    }
    SolverState::for_each_body_column([&](auto field) {
      const std::vector<double>& v = s.column(field);
      data.insert(data.end(), v.begin(), v.end());
    });
    data.insert(data.end(), s.bond_damage.begin(), s.bond_damage.end());
    data.insert(data.end(), s.bond_dissipated.begin(), s.bond_dissipated.end());
  }
  long long size = static_cast<long long>(data.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, comm_);
  data.resize(static_cast<std::size_t>(size));
  MPI_Bcast(data.data(), static_cast<int>(size), MPI_DOUBLE, 0, comm_);
  if (rank_ == 0) return;
  s = SolverState{};
  std::size_t at = 0;
  s.step = static_cast<std::int64_t>(data[at++]);
  s.time = data[at++];
  const auto pairs = static_cast<std::size_t>(data[at++]);
  SolverState::for_each_field([&](auto field) {
    for_each_array(s.column(field), [&](std::vector<double>& v, int) {
      v.assign(data.begin() + static_cast<std::ptrdiff_t>(at),
               data.begin() + static_cast<std::ptrdiff_t>(at + n_));
      at += n_;
    });
  });
  for (std::size_t p = 0; p < pairs; ++p) {
    s.pair_emitter.push_back(as_id(data[at++]));
    s.pair_partner.push_back(as_id(data[at++]));
    std::decay_t<decltype(s.pair_slip[0])> slip{};
    for (double& v : slip) v = data[at++];
    s.pair_slip.push_back(slip);
  }
  const std::size_t bodies = model_.bodies.size();
  SolverState::for_each_body_column([&](auto field) {
    s.column(field).assign(data.begin() + static_cast<std::ptrdiff_t>(at),
                           data.begin() + static_cast<std::ptrdiff_t>(at + bodies));
    at += bodies;
  });
  const std::size_t bonds = scene_.bonds.size(), points = SolverState::kBondStatePoints * bonds;
  s.bond_damage.assign(data.begin() + static_cast<std::ptrdiff_t>(at),
                       data.begin() + static_cast<std::ptrdiff_t>(at + points));
  at += points;
  s.bond_dissipated.assign(data.begin() + static_cast<std::ptrdiff_t>(at),
                           data.begin() + static_cast<std::ptrdiff_t>(at + bonds));
}

template <class Real>
std::string MpiSolver<Real>::global_ids(const std::string& message) const {
  // The local solver names its own indices; the user knows the scene's.
  static const std::regex id(R"((particles? |\) and )(\d+))");
  std::string out;
  auto last = message.cbegin();
  for (std::sregex_iterator m(message.begin(), message.end(), id), end; m != end; ++m) {
    out.append(last, (*m)[2].first);
    const auto k = std::stoull((*m)[2].str());
    out += k < global_.size() ? std::to_string(global_[k]) : (*m)[2].str();
    last = (*m)[2].second;
  }
  out.append(last, message.cend());
  return out;
}

template <class Real>
void MpiSolver<Real>::measure_bandwidth() {
  if (ranks_ < 2) return;
  // 1 MiB from every rank, spread over the others: what a first exchange moves per second.
  const std::size_t block = (std::size_t{1} << 17) / static_cast<std::size_t>(ranks_ - 1);
  std::vector<double> out(block * static_cast<std::size_t>(ranks_), 1.0), in(out.size());
  MPI_Barrier(comm_);
  const auto t0 = std::chrono::steady_clock::now();
  MPI_Alltoall(out.data(), static_cast<int>(block), MPI_DOUBLE, in.data(), static_cast<int>(block),
               MPI_DOUBLE, comm_);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double slowest = 0;
  MPI_Allreduce(&seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, comm_);
  const double bytes =
      static_cast<double>(block * sizeof(double) * static_cast<std::size_t>(ranks_ - 1));
  bandwidth_ = slowest > 0 ? bytes / slowest : 0;
}

template <class Real>
std::string MpiSolver<Real>::description() const {
  std::string ranks_on = "CPU ranks";
  if (gpu_) {
    ranks_on = "GPU ranks, on GPU";
    ranks_on += devices_.size() > 1 ? "s" : "";
    for (std::size_t r = 0; r < devices_.size(); ++r)
      ranks_on += fmt::format("{}{}", r == 0 ? " " : ", ", devices_[r]);
  }
  const std::string domains =
      plan_.grid() ? fmt::format("a grid of {} x {} domains", plan_.cuts[0], plan_.cuts[1])
                   : fmt::format("strips along {}", plan_.axis == 0 ? "x" : "y");
  return fmt::format("{} ranks of {}; {}, ghosts by MPI_Alltoallv {} ({}; {}), "
                     "first exchange {:.3g} GB/s per rank",
                     ranks_, local_->solver().description(), domains, local_->transport(), library_,
                     ranks_on, bandwidth_ / 1e9);
}

template <class Real>
std::string MpiSolver<Real>::statistics() const {
  std::size_t own = 0;
  for (std::int32_t g : global_)
    if (plan_.owns(rank_, g)) ++own;
  std::string s =
      fmt::format("{} plan{} (the first and {} after particles moved half the skin "
                  "{:.3g} m); rank 0 holds {} particles: {} its own",
                  plans_, plans_ == 1 ? "" : "s", plans_ - 1, skin_, global_.size(), own);
  s += fmt::format("; rank 0 waited {:.3g} s for its ghosts", exchange_wait_);
  GhostOverlapCounts c = earlier_overlap_;
  c += local_->overlap_counts();
  if (c.steps > 0)
    s += fmt::format("; rank 0 overlapped the ghost exchange with its own pairs on {} of {} "
                     "steps (list built on {}, {} of them after a ghost left its box; pairs on "
                     "ghosts touching on {})",
                     c.overlapped, c.steps, c.rebuilt, c.discarded, c.ghost_contacts);
  if (checkpoints_ > 0)
    s += fmt::format("; {} checkpoint{} written by the {} ranks side by side (MPI-IO), "
                     "{:.3g} MB in {:.3g} s",
                     checkpoints_, checkpoints_ == 1 ? "" : "s", ranks_, checkpoint_bytes_ / 1e6,
                     checkpoint_seconds_);
  return s;
}

template <class Real>
StageTimes MpiSolver<Real>::stage_times() const {
  StageTimes t = local_->solver().stage_times();
  for (int s = 0; s < kStageCount; ++s) t.seconds[s] += earlier_times_.seconds[s];
  t.steps += earlier_times_.steps;
  t.timed_steps += earlier_times_.timed_steps;
  return t;
}

template <class Real>
void MpiSolver<Real>::set_stage_timing(bool on) {
  timing_ = on;
  local_->solver().set_stage_timing(on);
}

template class MpiSolver<float>;
template class MpiSolver<double>;

}  // namespace tridem::mpi
