#include "core/place_numbered_solver.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "broadphase/emitter_rule.hpp"
#include "core/numbering_note.hpp"
#include "core/space_filling_order.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
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

  PlaceNumbering(PlaceOrder order, const Scene& scene, const ParticleModel& model)
      : scene_of(std::move(order.triangles)),
        inner_of(scene_of.size()),
        body_scene_of(std::move(order.bodies)),
        body_inner_of(body_scene_of.size()) {
    for (std::size_t k = 0; k < scene_of.size(); ++k)
      inner_of[static_cast<std::size_t>(scene_of[k])] = static_cast<std::int32_t>(k);
    for (std::size_t k = 0; k < body_scene_of.size(); ++k)
      body_inner_of[static_cast<std::size_t>(body_scene_of[k])] = static_cast<std::int32_t>(k);
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

/// The inner solver's contact copy (the CUDA solver's, beside the steps), its records
/// shown in the scene's ids. finish() gets the snapshot in the scene's ids, whose
/// positions it hands the inner copy in the inner order (the same values).
class PlaceNumberedContactCopy final : public ContactCopy {
 public:
  PlaceNumberedContactCopy(std::unique_ptr<ContactCopy> inner,
                           std::shared_ptr<const PlaceNumbering> numbering)
      : inner_(std::move(inner)), numbering_(std::move(numbering)) {}
  void start() override { inner_->start(); }
  void finish(Snapshot& s) override {
    staged_.step = s.step;
    staged_.time = s.time;
    gather(staged_.x, s.x, numbering_->scene_of);
    gather(staged_.y, s.y, numbering_->scene_of);
    staged_.contacts.clear();
    inner_->finish(staged_);
    s.contact_precision = staged_.contact_precision;
    numbering_->rename_contacts(staged_.contacts);
    append_records(staged_.contacts, s.contacts);
  }

 private:
  std::unique_ptr<ContactCopy> inner_;
  std::shared_ptr<const PlaceNumbering> numbering_;
  Snapshot staged_;  ///< the positions, in the inner order, and the inner records
};

class PlaceNumberedSolver final : public Solver {
 public:
  PlaceNumberedSolver(std::unique_ptr<Solver> inner, PlaceOrder order, const Scene& scene,
                      const ParticleModel& model)
      : inner_(std::move(inner)),
        numbering_(std::make_shared<const PlaceNumbering>(std::move(order), scene, model)) {}

  void advance(std::int64_t steps) override { inner_->advance(steps); }
  void snapshot(Snapshot& out, bool with_contacts) const override;
  /// The inner solver's copy, mapped; none when it has none (the CPU solvers: the time
  /// loop then takes the contacts with the snapshot).
  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    std::unique_ptr<ContactCopy> copy = inner_->make_contact_copy();
    if (!copy) return nullptr;
    return std::make_unique<PlaceNumberedContactCopy>(std::move(copy), numbering_);
  }
  void save_state(SolverState& out) const override;
  void load_state(const SolverState& in) override;
  EnergyBudget energy() const override { return inner_->energy(); }
  std::int64_t step() const override { return inner_->step(); }
  double time() const override { return inner_->time(); }
  double dt() const override { return inner_->dt(); }
  std::size_t size() const override { return inner_->size(); }
  std::string description() const override {
    return inner_->description() + ", particles numbered by place";
  }
  StageTimes stage_times() const override { return inner_->stage_times(); }
  void set_stage_timing(bool on) override { inner_->set_stage_timing(on); }
  std::string statistics() const override { return inner_->statistics(); }

 private:
  /// The contact history of `from` with its particles renamed by `id` (inner to scene ids,
  /// or back) into `to`: a pair whose emitter changes (two small particles whose order
  /// flips) sees the other side's displacement, −u (physics/contact_force.hpp: the history
  /// follows v_emitter − v_partner). `scene_ids`: the renamed ids are the scene's.
  void rename_pairs(const SolverState& from, SolverState& to, const std::vector<std::int32_t>& id,
                    bool scene_ids) const;
  /// v, one entry per inner particle (or body), put in the scene's order through inner_of.
  template <class T>
  void to_scene_order(std::vector<T>& v, const std::vector<std::int32_t>& inner_of) const;

  std::unique_ptr<Solver> inner_;
  std::shared_ptr<const PlaceNumbering> numbering_;
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
  inner_->snapshot(out, with_contacts);
  const PlaceNumbering& m = *numbering_;
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

void PlaceNumberedSolver::rename_pairs(const SolverState& from, SolverState& to,
                                       const std::vector<std::int32_t>& id, bool scene_ids) const {
  struct Row {
    std::int32_t emitter, partner;
    std::array<double, kSlipsPerPair> slip;
  };
  const std::vector<std::int32_t>& scene_of = numbering_->scene_of;
  std::vector<Row> rows(from.pairs());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    Row r{id[static_cast<std::size_t>(from.pair_emitter[k])],
          id[static_cast<std::size_t>(from.pair_partner[k])], from.pair_slip[k]};
    const std::int32_t a = scene_ids ? r.emitter : scene_of[static_cast<std::size_t>(r.emitter)];
    const std::int32_t b = scene_ids ? r.partner : scene_of[static_cast<std::size_t>(r.partner)];
    if (!numbering_->emits(r.emitter, r.partner, a, b)) {
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
  inner_->save_state(inner_state_);
  rename_particles(inner_state_, out, numbering_->inner_of, numbering_->body_inner_of);
  rename_pairs(inner_state_, out, numbering_->scene_of, true);
}

void PlaceNumberedSolver::load_state(const SolverState& in) {
  // Checked in the scene's ids, so that a problem names the particle the user knows.
  validate_solver_state(in, size(), numbering_->body_scene_of.size(), description());
  rename_particles(in, inner_state_, numbering_->scene_of, numbering_->body_scene_of);
  rename_pairs(in, inner_state_, numbering_->inner_of, false);
  inner_->load_state(inner_state_);
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

PlaceOrder place_order(const ParticleModel& model) {
  PlaceOrder out;
  const BodyModel& bodies = model.bodies;
  if (bodies.empty()) {
    // Lone triangles: the free ones, in the curve's order, take the free ones' places.
    const std::vector<std::size_t> rank = curve_rank(model.motion, model.centroid);
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
  const std::vector<std::size_t> rank = curve_rank(bodies.motion, bodies.centroid);
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

}  // namespace tridem
