#include "core/place_numbered_solver.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "broadphase/emitter_rule.hpp"
#include "core/neighbour_blocks.hpp"
#include "core/numbering_note.hpp"
#include "core/space_filling_order.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace tridem {

namespace {

/// out[k] = in[index[k]] for every k of `index`.
template <class Out, class In>
void gather(Out& out, const In& in, const std::vector<std::int32_t>& index) {
  const auto n = static_cast<std::int64_t>(index.size());
  out.resize(index.size());
#pragma omp parallel for schedule(static) if (n > 65536)
  for (std::int64_t k = 0; k < n; ++k) out[k] = in[static_cast<std::size_t>(index[k])];
}

/// −x, but +0 for either zero: a contact whose roles swap keeps "0" in the contacts CSV.
double flipped(double x) { return x == 0 ? 0.0 : -x; }

/// Sorts the rows of pairs by (emitter, partner).
template <class Row>
void sort_rows(std::vector<Row>& rows) {
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return a.emitter != b.emitter ? a.emitter < b.emitter : a.partner < b.partner;
  });
}

/// The two numberings of the particles, and the classes that say which particle of a pair
/// emits it: what the solver and its contact copy map by.
struct PlaceNumbering {
  std::vector<std::int32_t> scene_of;     ///< the scene id of the inner solver's particle k
  std::vector<std::int32_t> inner_of;     ///< the inner index of scene particle i
  std::vector<std::uint8_t> small, free;  ///< by scene id: the emitter rule's classes
  /// Bodies of several triangles (all empty without): as scene_of and inner_of, and the
  /// scene's first member of each body (n + 1 entries, Snapshot::body_first).
  std::vector<std::int32_t> body_scene_of, body_inner_of;
  std::vector<std::int64_t> body_first;
  /// The scene's own order (a large scene numbered by place, kept so until its grains
  /// mix): nothing to map.
  bool identity = true;

  PlaceNumbering(PlaceOrder order, const Scene& scene, const ParticleModel& model)
      : scene_of(std::move(order.triangles)),
        inner_of(scene_of.size()),
        body_scene_of(std::move(order.bodies)),
        body_inner_of(body_scene_of.size()) {
    for (std::size_t k = 0; k < scene_of.size(); ++k) {
      inner_of[static_cast<std::size_t>(scene_of[k])] = static_cast<std::int32_t>(k);
      identity = identity && scene_of[k] == static_cast<std::int32_t>(k);
    }
    for (std::size_t k = 0; k < body_scene_of.size(); ++k) {
      body_inner_of[static_cast<std::size_t>(body_scene_of[k])] = static_cast<std::int32_t>(k);
      identity = identity && body_scene_of[k] == static_cast<std::int32_t>(k);
    }
    if (!body_scene_of.empty()) body_first = model.bodies.first;
    // All-pairs has no size classes (broadphase/emitter_rule.hpp): every particle is small.
    small = scene.simulation.method == Method::AllPairs
                ? std::vector<std::uint8_t>(model.size(), 1)
                : classify_for_grid(model.longest_edge, model.motion).small;
    free.resize(model.size());
    for (std::size_t i = 0; i < model.size(); ++i) free[i] = model.motion[i] == Motion::Free;
  }

  /// Whether particle i emits the pair (i, j) in the numbering the ids i and j are of;
  /// a and b are their scene ids (their classes).
  bool emits(std::int32_t i, std::int32_t j, std::int32_t a, std::int32_t b) const {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    return emits_pair(i, j, small[ua] != 0, small[ub] != 0, free[ua] != 0, free[ub] != 0);
  }

  /// Renames the inner solver's contact records to the scene's ids, each seen from the
  /// pair's emitter in the scene's numbering; they stay in the inner solver's order (along
  /// the curve). Put in the scene's emitter order instead, a frame of 10^6 grains at random
  /// took 1.2 s more on 2 cores: 6x10^6 records of 88 bytes moved at random.
  void rename_contacts(std::vector<ContactRecord>& records) const;
};

void PlaceNumbering::rename_contacts(std::vector<ContactRecord>& records) const {
  if (identity) return;
  const auto count = static_cast<std::int64_t>(records.size());
#pragma omp parallel for schedule(static) if (count > 65536)
  for (std::int64_t k = 0; k < count; ++k) {
    ContactRecord& r = records[static_cast<std::size_t>(k)];
    const std::int32_t a = scene_of[static_cast<std::size_t>(r.i)];
    const std::int32_t b = scene_of[static_cast<std::size_t>(r.j)];
    if (emits(a, b, a, b)) {
      r.i = a;
      r.j = b;
    } else {
      // Seen from the other particle: the force on it, the normal into its partner, the
      // translation of its own image.
      r.i = b;
      r.j = a;
      for (double* v : {&r.fx, &r.fy, &r.nx, &r.ny, &r.image_dx, &r.image_dy}) *v = flipped(*v);
    }
  }
}

/// Appends `from` to `to`, by a swap of the two when `to` is empty (a frame's contacts:
/// hundreds of megabytes at 10^6 grains), leaving `from` with `to`'s old buffer to reuse.
void append_records(std::vector<ContactRecord>& from, std::vector<ContactRecord>& to) {
  if (to.empty())
    to.swap(from);
  else
    to.insert(to.end(), from.begin(), from.end());
}

/// Throws RunError unless `order` is one the solver could have renumbered `scene` to: every
/// particle once, walls in their places, bodies as wholes with their members in order.
void check_order(const PlaceOrder& order, const Scene& scene, const ParticleModel& model,
                 const std::string& source) {
  auto refuse = [&](const std::string& why) {
    throw RunError(fmt::format("{}: the state's particle order {}: it is not one this scene's "
                               "solver numbers its particles in (a damaged checkpoint, or one "
                               "of another scene)",
                               source, why));
  };
  const std::size_t n = model.size();
  if (order.triangles.size() != n)
    refuse(fmt::format("has {} entries for {} particles", order.triangles.size(), n));
  std::vector<std::uint8_t> seen(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t i = order.triangles[k];
    if (i < 0 || static_cast<std::size_t>(i) >= n || seen[static_cast<std::size_t>(i)] != 0)
      refuse(fmt::format("names particle {} at place {} (out of range or twice)", i, k));
    seen[static_cast<std::size_t>(i)] = 1;
    if ((model.motion[k] != Motion::Free ||
         model.motion[static_cast<std::size_t>(i)] != Motion::Free) &&
        i != static_cast<std::int32_t>(k))
      refuse(fmt::format("moves wall particle {} or puts a grain in its place", k));
  }
  const std::size_t nb = model.bodies.size();
  if (order.bodies.size() != (nb == 0 ? 0 : nb))
    refuse(fmt::format("has {} bodies for {}", order.bodies.size(), nb));
  if (nb == 0) return;
  std::vector<std::uint8_t> seen_body(nb, 0);
  for (const std::int32_t b : order.bodies) {
    if (b < 0 || static_cast<std::size_t>(b) >= nb || seen_body[static_cast<std::size_t>(b)] != 0)
      refuse(fmt::format("names body {} out of range or twice", b));
    seen_body[static_cast<std::size_t>(b)] = 1;
  }
  if (body_order(scene, order.bodies).triangles != order.triangles)
    refuse("does not keep each body's members together and in order");
}

/// The inner solver and its numbering, which the wrapper replaces when it renumbers, shared
/// with the contact copies: a copy makes its inner copy from the inner solver of the time
/// it starts, and the wrapper does not replace a solver while a copy of its contacts is in
/// flight (the CUDA copy's download reads the solver's buffers).
struct InnerSolver {
  std::unique_ptr<Solver> solver;
  std::shared_ptr<const PlaceNumbering> numbering;
  std::uint64_t generation = 0;  ///< how many times the solver was replaced
  std::mutex mutex;
  std::condition_variable copied;
  bool copying = false;  ///< a copy has started and not finished

  void wait_for_copies() {
    std::unique_lock lock(mutex);
    copied.wait(lock, [this] { return !copying; });
  }
};

/// The inner solver's contact copy (the CUDA solver's, beside the steps), its records
/// shown in the scene's ids. finish() gets the snapshot in the scene's ids, whose
/// positions it hands the inner copy in the inner order (the same values).
class PlaceNumberedContactCopy final : public ContactCopy {
 public:
  explicit PlaceNumberedContactCopy(std::shared_ptr<InnerSolver> inner)
      : inner_(std::move(inner)) {}
  void start() override {
    {
      const std::lock_guard lock(inner_->mutex);
      if (!copy_ || generation_ != inner_->generation) {
        copy_ = inner_->solver->make_contact_copy();
        if (!copy_) throw RunError("internal error: a renumbered solver has no contact copy");
        numbering_ = inner_->numbering;
        generation_ = inner_->generation;
      }
      inner_->copying = true;
    }
    try {
      copy_->start();
    } catch (...) {
      done();
      throw;
    }
  }
  void finish(Snapshot& s) override {
    struct Done {
      PlaceNumberedContactCopy* copy;
      ~Done() { copy->done(); }
    } done_at_exit{this};
    if (numbering_->identity) {
      copy_->finish(s);
      return;
    }
    staged_.step = s.step;
    staged_.time = s.time;
    gather(staged_.x, s.x, numbering_->scene_of);
    gather(staged_.y, s.y, numbering_->scene_of);
    staged_.contacts.clear();
    copy_->finish(staged_);
    s.contact_precision = staged_.contact_precision;
    numbering_->rename_contacts(staged_.contacts);
    append_records(staged_.contacts, s.contacts);
  }

 private:
  void done() {
    {
      const std::lock_guard lock(inner_->mutex);
      inner_->copying = false;
    }
    inner_->copied.notify_all();
  }

  std::shared_ptr<InnerSolver> inner_;
  std::unique_ptr<ContactCopy> copy_;
  std::shared_ptr<const PlaceNumbering> numbering_;
  std::uint64_t generation_ = 0;
  Snapshot staged_;  ///< the positions, in the inner order, and the inner records
};

/// What a solver needs to number its particles by place again mid-run.
struct Renumbering {
  Scene scene;  ///< the scene (its model is built again when it renumbers)
  MakeInnerSolver make;
  std::int64_t check_steps = 0;
  double scattered = kScatteredNeighbours;  ///< mixed: neighbour_block_spread beyond
  double grain_size = 0;                    ///< the free particles' mean size
  double body_size = 0;                     ///< the free bodies' mean size (the root of their area)
  std::vector<std::uint8_t> free_body;      ///< by scene body id
  std::int64_t count = 0;                   ///< how many times it renumbered
};

class PlaceNumberedSolver final : public Solver {
 public:
  PlaceNumberedSolver(std::unique_ptr<Solver> inner, PlaceOrder order, const Scene& scene,
                      const ParticleModel& model, std::unique_ptr<Renumbering> renumbering = {})
      : inner_(std::make_shared<InnerSolver>()), renumbering_(std::move(renumbering)) {
    inner_->solver = std::move(inner);
    inner_->numbering = std::make_shared<const PlaceNumbering>(std::move(order), scene, model);
  }

  void advance(std::int64_t steps) override;
  void snapshot(Snapshot& out, bool with_contacts) const override;
  /// The inner solver's copy, mapped; none when it has none (the CPU solvers: the time
  /// loop then takes the contacts with the snapshot).
  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    if (!solver().make_contact_copy()) return nullptr;
    return std::make_unique<PlaceNumberedContactCopy>(inner_);
  }
  void save_state(SolverState& out) const override;
  void load_state(const SolverState& in) override;
  EnergyBudget energy() const override { return solver().energy(); }
  std::int64_t step() const override { return solver().step(); }
  double time() const override { return solver().time(); }
  double dt() const override { return solver().dt(); }
  std::size_t size() const override { return solver().size(); }
  std::string description() const override {
    return solver().description() +
           (numbering().identity ? std::string() : ", particles numbered by place");
  }
  StageTimes stage_times() const override;
  void set_stage_timing(bool on) override {
    stage_timing_ = on;
    solver().set_stage_timing(on);
  }
  std::string statistics() const override {
    std::string s = solver().statistics();
    if (renumbering_ && renumbering_->count > 0)
      s += fmt::format("; numbered by place again {} time{} as the grains mixed",
                       renumbering_->count, renumbering_->count == 1 ? "" : "s");
    return s;
  }

 private:
  Solver& solver() const { return *inner_->solver; }
  const PlaceNumbering& numbering() const { return *inner_->numbering; }
  /// Whether the neighbours of the inner solver's consecutive free particles (or bodies)
  /// have scattered in memory (core/neighbour_blocks.hpp).
  bool mixed() const;
  /// The inner solver replaced by one of `state`'s particles (in the scene's ids) in
  /// `order`, continuing from `state`.
  void replace_inner(PlaceOrder order, const ParticleModel& model, const SolverState& state);
  /// The contact history of `from` with its particles renamed by `id` (inner to scene ids,
  /// or back) into `to`: a pair whose emitter changes (two small particles whose order
  /// flips) sees the other side's displacement, −u (physics/contact_force.hpp: the history
  /// follows v_emitter − v_partner). `scene_ids`: the renamed ids are the scene's.
  void rename_pairs(const SolverState& from, SolverState& to, const std::vector<std::int32_t>& id,
                    bool scene_ids) const;
  /// v, one entry per inner particle (or body), put in the scene's order through inner_of.
  template <class T>
  void to_scene_order(std::vector<T>& v, const std::vector<std::int32_t>& inner_of) const;

  std::shared_ptr<InnerSolver> inner_;
  std::unique_ptr<Renumbering> renumbering_;
  StageTimes retired_times_;  ///< the stage times of the solvers replaced so far
  /// The order is the one make_solver picks from the scene (a state need not carry it).
  bool order_from_scene_ = true;
  std::optional<bool> stage_timing_;  ///< as set, for the solvers that replace the inner one
  /// to_scene_order's spare array of each type a snapshot's arrays have.
  mutable std::tuple<std::vector<double>, std::vector<int>, std::vector<Motion>> spare_;
  mutable SolverState inner_state_;
};

template <class T>
void PlaceNumberedSolver::to_scene_order(std::vector<T>& v,
                                         const std::vector<std::int32_t>& inner_of) const {
  std::vector<T>& spare = std::get<std::vector<T>>(spare_);
  gather(spare, v, inner_of);
  v.swap(spare);  // the spare keeps the old buffer: no allocation after the first frame
}

// The inner solver writes its snapshot into `out` in its own order, which is then put in
// the scene's in place, one array at a time: no second snapshot (at 10^6 grains with their
// contacts some 0.7 GB) is kept.
void PlaceNumberedSolver::snapshot(Snapshot& out, bool with_contacts) const {
  solver().snapshot(out, with_contacts);
  const PlaceNumbering& m = numbering();
  if (m.identity) return;
  out.for_each_particle_array(out, [&](auto& v, auto&) { to_scene_order(v, m.inner_of); });
  if (!m.body_scene_of.empty()) {
    Snapshot::for_each_body_column(
        [&](auto field) { to_scene_order(out.column(field), m.body_inner_of); });
    to_scene_order(out.body_mass, m.body_inner_of);
    to_scene_order(out.body_inertia, m.body_inner_of);
    out.body_first = m.body_first;
    // A member's body: the scene's id of the body of the inner particle at its place.
    to_scene_order(out.member_body, m.inner_of);
    for (std::int32_t& b : out.member_body) b = m.body_scene_of[static_cast<std::size_t>(b)];
  }
  for (auto* ends : {&out.bond_a, &out.bond_b})
    for (std::int32_t& i : *ends) i = m.scene_of[static_cast<std::size_t>(i)];
  if (with_contacts) m.rename_contacts(out.contacts);
}

StageTimes PlaceNumberedSolver::stage_times() const {
  StageTimes t = solver().stage_times();
  if (retired_times_.steps == 0) return t;
  for (int k = 0; k < kStageCount; ++k) t.seconds[k] += retired_times_.seconds[k];
  t.steps += retired_times_.steps;
  t.timed_steps += retired_times_.timed_steps;
  return t;
}

// The looks at the order fall on the steps that are multiples of check_steps whatever the
// calls' sizes, and what they find is a function of the state: a run and its restart from
// any checkpoint renumber at the same steps, to the same order.
void PlaceNumberedSolver::advance(std::int64_t steps) {
  while (steps > 0) {
    std::int64_t chunk = steps;
    const std::int64_t every = renumbering_ ? renumbering_->check_steps : 0;
    if (every > 0) chunk = std::min(chunk, every - step() % every);
    solver().advance(chunk);
    steps -= chunk;
    if (every > 0 && step() % every == 0 && mixed()) {
      const ParticleModel model = build_particle_model(renumbering_->scene);
      SolverState state;
      save_state(state);
      replace_inner(place_order(model, state), model, state);
      ++renumbering_->count;
    }
  }
}

bool PlaceNumberedSolver::mixed() const {
  Snapshot now;
  solver().snapshot(now, false);
  const PlaceNumbering& m = numbering();
  // Bodies of several triangles: their members lie together whatever the order, so the
  // bodies' centroids tell where consecutive ones' neighbours lie.
  const bool bodies = !m.body_scene_of.empty();
  const std::vector<double>& x = bodies ? now.body_x : now.x;
  const std::vector<double>& y = bodies ? now.body_y : now.y;
  const std::vector<std::int32_t>& scene_of = bodies ? m.body_scene_of : m.scene_of;
  const std::vector<std::uint8_t>& free = bodies ? renumbering_->free_body : m.free;
  std::vector<Vec2d> centroid(x.size());
  std::vector<std::uint8_t> inner_free(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    centroid[k] = {x[k], y[k]};
    inner_free[k] = free[static_cast<std::size_t>(scene_of[k])];
  }
  const double size = bodies ? renumbering_->body_size : renumbering_->grain_size;
  return neighbour_block_spread(centroid, inner_free, size) > renumbering_->scattered;
}

void PlaceNumberedSolver::replace_inner(PlaceOrder order, const ParticleModel& model,
                                        const SolverState& state) {
  inner_->wait_for_copies();
  const StageTimes t = solver().stage_times();
  for (int k = 0; k < kStageCount; ++k) retired_times_.seconds[k] += t.seconds[k];
  retired_times_.steps += t.steps;
  retired_times_.timed_steps += t.timed_steps;
  const Scene& scene = renumbering_->scene;
  auto solver_in = [&](const PlaceOrder& o) {
    return scene.bonds.empty()
               ? renumbering_->make(scene, reordered_model(scene, model, o))
               : renumbering_->make(reordered_scene(scene, o), reordered_model(scene, model, o));
  };
  std::exception_ptr failure;
  {
    const std::lock_guard lock(inner_->mutex);
    const PlaceOrder before{numbering().scene_of, numbering().body_scene_of};
    inner_->solver.reset();  // its memory (the GPU's) goes before the new solver's comes
    try {
      inner_->solver = solver_in(order);
      inner_->numbering = std::make_shared<const PlaceNumbering>(std::move(order), scene, model);
      order_from_scene_ = false;
    } catch (...) {
      // Out of memory, say: the state goes back into a solver in the order it had, so that
      // what reads the solver next (a failed run's last good state) finds it; then the
      // failure goes on.
      failure = std::current_exception();
      inner_->solver = solver_in(before);
    }
    ++inner_->generation;
  }
  if (stage_timing_) solver().set_stage_timing(*stage_timing_);
  load_state(state);
  if (failure) std::rethrow_exception(failure);
}
void PlaceNumberedSolver::rename_pairs(const SolverState& from, SolverState& to,
                                       const std::vector<std::int32_t>& id, bool scene_ids) const {
  struct Row {
    std::int32_t emitter, partner;
    std::array<double, kSlipsPerPair> slip;
  };
  const std::vector<std::int32_t>& scene_of = numbering().scene_of;
  std::vector<Row> rows(from.pairs());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    Row r{id[static_cast<std::size_t>(from.pair_emitter[k])],
          id[static_cast<std::size_t>(from.pair_partner[k])], from.pair_slip[k]};
    const std::int32_t a = scene_ids ? r.emitter : scene_of[static_cast<std::size_t>(r.emitter)];
    const std::int32_t b = scene_ids ? r.partner : scene_of[static_cast<std::size_t>(r.partner)];
    if (!numbering().emits(r.emitter, r.partner, a, b)) {
      std::swap(r.emitter, r.partner);
      for (double& u : r.slip) u = -u;
    }
    rows[k] = r;
  }
  sort_rows(rows);
  to.pair_emitter.resize(rows.size());
  to.pair_partner.resize(rows.size());
  to.pair_slip.resize(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    to.pair_emitter[k] = rows[k].emitter;
    to.pair_partner[k] = rows[k].partner;
    to.pair_slip[k] = rows[k].slip;
  }
}

/// Every per-particle column of `to` from `from` through `index` (an empty column, the
/// energy sums' zeros, stays empty); the rest of the state as it is.
void rename_particles(const SolverState& from, SolverState& to,
                      const std::vector<std::int32_t>& index,
                      const std::vector<std::int32_t>& body_index) {
  to.step = from.step;
  to.time = from.time;
  SolverState::for_each_field([&](auto field) {
    for_each_array(to.column(field), [&](auto& t, int k) {
      const auto& f = array_at(from.column(field), k);
      if (f.empty())
        t.clear();
      else
        gather(t, f, index);
    });
  });
  SolverState::for_each_body_column([&](auto field) {
    if (from.column(field).empty())
      to.column(field).clear();
    else
      gather(to.column(field), from.column(field), body_index);
  });
  to.bond_damage = from.bond_damage;
  to.bond_dissipated = from.bond_dissipated;
}

void PlaceNumberedSolver::save_state(SolverState& out) const {
  const PlaceNumbering& m = numbering();
  if (m.identity) {
    solver().save_state(out);
  } else {
    solver().save_state(inner_state_);
    rename_particles(inner_state_, out, m.inner_of, m.body_inner_of);
    rename_pairs(inner_state_, out, m.scene_of, true);
  }
  // The order goes with the state once it is no longer the one the scene alone gives.
  out.particle_order.clear();
  out.body_order.clear();
  if (!order_from_scene_) {
    out.particle_order = m.scene_of;
    out.body_order = m.body_scene_of;
  }
}

void PlaceNumberedSolver::load_state(const SolverState& in) {
  const PlaceNumbering& m = numbering();
  // Checked in the scene's ids, so that a problem names the particle the user knows.
  validate_solver_state(in, size(), m.body_scene_of.size(), description());
  if (renumbering_ && !in.particle_order.empty() &&
      (in.particle_order != m.scene_of || in.body_order != m.body_scene_of)) {
    // A run renumbered mid-way continues in the order it had, so that it goes on bit for
    // bit as it would have without the stop.
    const ParticleModel model = build_particle_model(renumbering_->scene);
    PlaceOrder order{in.particle_order, in.body_order};
    check_order(order, renumbering_->scene, model, description());
    replace_inner(std::move(order), model, in);
    return;
  }
  if (m.identity) {
    solver().load_state(in);
    return;
  }
  rename_particles(in, inner_state_, m.scene_of, m.body_scene_of);
  rename_pairs(in, inner_state_, m.inner_of, false);
  solver().load_state(inner_state_);
}

}  // namespace

bool numbers_by_place(const Scene& scene, const ParticleModel& model, ParticleOrder order) {
  if (order == ParticleOrder::Scene) return false;
  // The solver's pairs and bonds index particles by 32-bit ids.
  const bool too_many = model.size() > static_cast<std::size_t>(INT32_MAX);
  if (order == ParticleOrder::Place) {
    if (too_many)
      throw RunError(fmt::format("{}: particle order \"place\" renumbers at most 2^31 "
                                 "particles: give particle order \"scene\" or \"auto\"",
                                 scene_label(scene)));
    return true;
  }
  return !too_many && model.size() >= kLargeNumbering &&
         consecutive_id_distance(model) > kFarNumbering;
}

namespace {

/// Each item's position along the curve among the free ones (by their centroids); the
/// others' entries are unused.
std::vector<std::size_t> curve_rank(const std::vector<Motion>& motion,
                                    const std::vector<Vec2d>& centroid) {
  std::vector<std::size_t> free, rank(motion.size(), 0);
  std::vector<Vec2d> points;
  for (std::size_t i = 0; i < motion.size(); ++i)
    if (motion[i] == Motion::Free) {
      free.push_back(i);
      points.push_back(centroid[i]);
    }
  const std::vector<std::size_t> along = space_filling_order(points);
  for (std::size_t k = 0; k < along.size(); ++k) rank[free[along[k]]] = k;
  return rank;
}

}  // namespace

namespace {

/// place_order with the particles' centroids at `centroid` and the bodies' at
/// `body_centroid` (the model's, or a state's now).
PlaceOrder place_order_at(const ParticleModel& model, const std::vector<Vec2d>& centroid,
                          const std::vector<Vec2d>& body_centroid) {
  PlaceOrder out;
  const BodyModel& bodies = model.bodies;
  if (bodies.empty()) {
    // Lone triangles: the free ones, in the curve's order, take the free ones' places.
    const std::vector<std::size_t> rank = curve_rank(model.motion, centroid);
    std::vector<std::int32_t> free;
    out.triangles.resize(model.size());
    for (std::size_t i = 0; i < model.size(); ++i) {
      out.triangles[i] = static_cast<std::int32_t>(i);
      if (model.motion[i] == Motion::Free) free.push_back(static_cast<std::int32_t>(i));
    }
    for (const std::int32_t i : free) out.triangles[free[rank[static_cast<std::size_t>(i)]]] = i;
    return out;
  }
  // Bodies, as wholes: each run of consecutive free bodies in the curve's order, so that the
  // run covers the same triangles and every wall body keeps its members' ids.
  const std::vector<std::size_t> rank = curve_rank(bodies.motion, body_centroid);
  const std::size_t nb = bodies.size();
  out.bodies.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) out.bodies[b] = static_cast<std::int32_t>(b);
  for (std::size_t b = 0; b < nb;) {
    if (bodies.motion[b] != Motion::Free) {
      ++b;
      continue;
    }
    std::size_t end = b;
    while (end < nb && bodies.motion[end] == Motion::Free) ++end;
    std::sort(out.bodies.begin() + static_cast<std::ptrdiff_t>(b),
              out.bodies.begin() + static_cast<std::ptrdiff_t>(end),
              [&](std::int32_t x, std::int32_t y) {
                return rank[static_cast<std::size_t>(x)] < rank[static_cast<std::size_t>(y)];
              });
    b = end;
  }
  out.triangles.reserve(model.size());
  for (const std::int32_t b : out.bodies)
    for (std::int64_t i = bodies.first[static_cast<std::size_t>(b)];
         i < bodies.first[static_cast<std::size_t>(b) + 1]; ++i)
      out.triangles.push_back(static_cast<std::int32_t>(i));
  return out;
}

}  // namespace

PlaceOrder place_order(const ParticleModel& model) {
  return place_order_at(model, model.centroid, model.bodies.centroid);
}

PlaceOrder place_order(const ParticleModel& model, const SolverState& now) {
  auto points = [](const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<Vec2d> p(x.size());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = {x[i], y[i]};
    return p;
  };
  return place_order_at(model, points(now.x, now.y), points(now.body_x, now.body_y));
}

PlaceOrder body_order(const Scene& scene, std::vector<std::int32_t> bodies) {
  PlaceOrder order;
  order.triangles.reserve(scene.triangles.size());
  for (const std::int32_t b : bodies) {
    const BodySpec& body = scene.bodies[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < body.count; ++k)
      order.triangles.push_back(static_cast<std::int32_t>(body.first + k));
  }
  order.bodies = std::move(bodies);
  return order;
}

Scene reordered_scene(const Scene& scene, const PlaceOrder& order) {
  Scene inner;
  inner.source = scene.source;
  inner.simulation = scene.simulation;
  inner.output = scene.output;
  inner.materials = scene.materials;
  inner.programs = scene.programs;
  inner.program_knots = scene.program_knots;
  inner.triangles.reserve(scene.triangles.size());
  for (const std::int32_t i : order.triangles)
    inner.triangles.push_back(scene.triangles[static_cast<std::size_t>(i)]);
  std::size_t first = 0;
  for (const std::int32_t b : order.bodies) {
    BodySpec body = scene.bodies[static_cast<std::size_t>(b)];
    body.first = first;
    first += body.count;
    inner.bodies.push_back(body);
  }
  if (!scene.bonds.empty()) {
    std::vector<std::size_t> inner_of(order.triangles.size());
    for (std::size_t k = 0; k < order.triangles.size(); ++k)
      inner_of[static_cast<std::size_t>(order.triangles[k])] = k;
    inner.bonds.reserve(scene.bonds.size());
    for (BondSpec bond : scene.bonds) {
      bond.a = inner_of[bond.a];
      bond.b = inner_of[bond.b];
      inner.bonds.push_back(bond);
    }
  }
  return inner;
}

ParticleModel reordered_model(const Scene& scene, const ParticleModel& model,
                              const PlaceOrder& order) {
  if (order.bodies.empty()) {
    ParticleModel out;
    out.for_each_particle_array(
        model, [&](auto& to, const auto& from) { gather(to, from, order.triangles); });
    out.programs = model.programs;
    out.program_knots = model.program_knots;
    out.bodies = model.bodies;
    out.shown_ids.particle.assign(order.triangles.begin(), order.triangles.end());
    return out;
  }
  // Bodies: the model of the scene in the new order, built as any scene's (a body's mass,
  // inertia and members' offsets sum its members, in their own order: the same bits).
  const Scene inner = reordered_scene(scene, order);
  ParticleModel out = build_particle_model(inner);
  out.shown_ids.particle.assign(order.triangles.begin(), order.triangles.end());
  out.shown_ids.body.assign(order.bodies.begin(), order.bodies.end());
  return out;
}

std::unique_ptr<Solver> make_place_numbered_solver(std::unique_ptr<Solver> inner, PlaceOrder order,
                                                   const Scene& scene, const ParticleModel& model) {
  return std::make_unique<PlaceNumberedSolver>(std::move(inner), std::move(order), scene, model);
}

std::unique_ptr<Solver> make_renumbering_solver(const Scene& scene, const ParticleModel& model,
                                                PlaceOrder order, const MakeInnerSolver& make,
                                                std::int64_t check_steps, double scattered) {
  const PlaceNumbering initial(order, scene, model);
  std::unique_ptr<Solver> inner;
  if (initial.identity)
    inner = make(scene, model);
  else if (scene.bonds.empty())  // the solver reads a scene's settings and bonds, not its triangles
    inner = make(scene, reordered_model(scene, model, order));
  else
    inner = make(reordered_scene(scene, order), reordered_model(scene, model, order));
  auto renumbering = std::make_unique<Renumbering>();
  renumbering->scene = scene;
  renumbering->make = make;
  renumbering->check_steps = check_steps;
  renumbering->scattered = scattered;
  renumbering->grain_size = free_grain_size(model);
  const BodyModel& bodies = model.bodies;
  renumbering->free_body.resize(bodies.size());
  double body_sizes = 0;
  std::size_t free_bodies = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    renumbering->free_body[b] = bodies.motion[b] == Motion::Free;
    if (bodies.motion[b] != Motion::Free) continue;
    double area = 0;
    for (std::int64_t i = bodies.first[b]; i < bodies.first[b + 1]; ++i)
      area += model.area[static_cast<std::size_t>(i)];
    body_sizes += std::sqrt(area);
    ++free_bodies;
  }
  if (free_bodies > 0) renumbering->body_size = body_sizes / static_cast<double>(free_bodies);
  return std::make_unique<PlaceNumberedSolver>(std::move(inner), std::move(order), scene, model,
                                               std::move(renumbering));
}

PlaceOrder scene_order(const ParticleModel& model) {
  PlaceOrder order;
  order.triangles.resize(model.size());
  std::iota(order.triangles.begin(), order.triangles.end(), 0);
  if (!model.bodies.empty()) {
    order.bodies.resize(model.bodies.size());
    std::iota(order.bodies.begin(), order.bodies.end(), 0);
  }
  return order;
}

}  // namespace tridem
