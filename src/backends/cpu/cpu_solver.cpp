#include "backends/cpu/cpu_solver.hpp"

#include "broadphase/history_carry.hpp"
#include "broadphase/pair_sums.hpp"
#include "broadphase/row_energy.hpp"
#include "core/memory_estimate.hpp"
#include "core/omp_team.hpp"
#include "core/omp_threads.hpp"
#include "core/particle_columns.hpp"
#include "core/runaway_message.hpp"
#include "core/snapshot_fill.hpp"

#include "physics/integrate.hpp"
#include "physics/local_frame.hpp"
#include "physics/motion_program.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <omp.h>

namespace tridem {

template <class Real>
CpuSolver<Real>::CpuSolver(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
                           const SolverConfig& config, bool parallel)
    : n_(model.size()),
      openmp_(parallel),
      parallel_(parallel),
      choice_(parallel, config.thread_use),
      threads_(parallel ? config.threads : 0),
      method_(scene.simulation.method),
      dt_(ts.chosen),
      gravity_(scene.simulation.gravity),
      local_damping_(scene.simulation.local_damping),
      penetration_limit_(static_cast<Real>(scene.simulation.max_penetration)),
      limit_(ts),
      n_materials_(static_cast<int>(scene.materials.size())),
      finder_(model.longest_edge, model.motion),
      filter_{scene.simulation.contact_test, scene.simulation.bbox_prefilter},
      single_domain_(model.longest_edge, model.motion, filter_) {
  if (method_ == Method::Decomposition)
    decomposed_.emplace(scene.simulation.decomposition, model.longest_edge, model.motion,
                        filter_);
  for_each_particle_field([&](auto field) {
    for_each_array(column(field),
                   [&](auto& v, int k) { v = initial_column<Real>(field, model, k); });
  });
  partner_.resize(n_);
  margin_ = static_cast<Real>(scene.simulation.skin * static_cast<double>(finder_.cell_size()));
  walls_move_ = walls_move(model);
  cell_ = scene.simulation.periodic;
  periodic_ = cell_.any();
  keeps_lists_ = can_take_ghosts_mid_step();
  if (keeps_lists_)
    for (auto* v : {&build_lo_x_, &build_lo_y_, &build_hi_x_, &build_hi_y_}) v->assign(n_, Real(0));
  if (periodic_ && cell_.shear_rate != 0) image_power_.assign(n_, 0.0);
  programs_ = model.programs;
  program_knots_ = model.program_knots;
  shown_ids_ = model.shown_ids;
  if (std::any_of(programs_.begin(), programs_.end(), physics::follows_length))
    servo_targets_.assign(programs_.size(), 0.0);
  if (!model.bodies.empty()) {
    const BodyModel& bm = model.bodies;
    n_bodies_ = bm.size();
    for_each_body_field(
        [&](auto field) { column(field) = initial_body_column(field, bm, n_bodies_); });
    for_each_member_field([&](auto field) { column(field) = initial_body_column(field, bm, n_); });
    on_team(false, [&] { place_members(); });
  }
  for (const auto& law : contact_law_table(scene.materials))
    laws_.push_back(physics::SceneContactLaw::cast<Real>(law));
  if (!scene.bonds.empty()) {
    bonds_ = initial_bond_columns<Real>(build_bond_model(scene, model));
    bond_view_ = bonds_.view(bonds_.size());
  }
  // Room for a dense packing's pairs up front, reserved, not filled: the lists take what
  // they list (grow_to, within the room without allocating) and only grow past it. Filled,
  // the room's pages were written once at set-up, most of them for nothing: 2.5 of a 10^6
  // lattice's 3.2 s set-up here.
  const std::size_t initial_pairs = reserved_pairs(n_);
  for (PairList* p : {&pairs_, &old_pairs_}) {
    p->offset.assign(n_ + 1, 0);
    p->partner.reserve(initial_pairs);
  }
  slip_.reserve(initial_pairs);
  old_slip_.reserve(initial_pairs);
  result_.reserve(initial_pairs);
}

template <class Real>
std::string CpuSolver<Real>::description() const {
  const std::string real =
      precision_description(sizeof(Real) == 8 ? Precision::Double : Precision::Float);
  const std::string method = method_description(method_, filter_.test, filter_.bbox_prefilter);
  if (openmp_)
    return fmt::format("{} ({} threads), {}, {}", backend_name(Backend::OpenMP),
                       threads_ > 0 ? threads_ : omp_get_max_threads(), real, method);
  return fmt::format("{} (serial), {}, {}", backend_name(Backend::Cpu), real, method);
}

template <class Real>
std::string CpuSolver<Real>::statistics() const {
  std::string s = decomposed_ ? decomposed_->decomposition().summary() : std::string();
  if (keeps_lists_ && !take_ghosts_)
    s += fmt::format("pair list built {} times in {} steps (skin {:.3g} m)", list_builds_,
                     choice_.steps(), static_cast<double>(margin_));
  const std::int64_t one = choice_.steps() - choice_.parallel_steps();
  if (openmp_ && one > 0)
    s += fmt::format("{}{} of {} steps on one thread, timed faster than the threads on "
                     "these cores ({} switches)",
                     s.empty() ? "" : "; ", one, choice_.steps(), choice_.switches());
  return s;
}

template <class Real>
void CpuSolver<Real>::advance(std::int64_t steps) {
  const ScopedOmpThreads threads(threads_);
  for (std::int64_t s = 0; s < steps; ++s) {
    parallel_ = choice_.parallel();
    pair_energy_ = s + 1 == steps;
    // A step that throws leaves no list to keep (its build boxes may be a newer list's).
    may_keep_ = list_kept_;
    list_kept_ = false;
    const auto start = std::chrono::steady_clock::now();
    run_step_on_team();
    choice_.record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::swap(pairs_, old_pairs_);
    std::swap(slip_, old_slip_);
    list_kept_ = keeps_lists_;
    if (take_ghosts_) {
      ++overlap_counts_.steps;
      if (ghost_contact_ != 0) ++overlap_counts_.ghost_contacts;
    }
    ++step_;
    time_ += dt_;
  }
}

// One step, one parallel region (issue 12): every stage is team code (core/omp_team.hpp),
// its loops shared out to the threads of one team that lives for the whole step, instead
// of a region per loop (a dozen forks and joins a step). The clock works as run_step's
// (core/stage_pipeline.hpp): read by the first thread once each stage's last loop has
// ended on every thread; a stage that throws ends the step before the clock counts it.
template <class Real>
void CpuSolver<Real>::run_step_on_team() {
  StageStopwatch& clock = stopwatch_;
  const bool timed = clock.on && clock.sample_this_step();
  const auto start = std::chrono::steady_clock::now();
  if (timed) clock.begin_step();
  too_deep_ = kNoIndex;
  first_runaway_ = kNoIndex;
  left_box_ = 0;
  ghost_contact_ = 0;
  // From the poses at the step's start, which only Integrate changes; read by Check and
  // Integrate.
  if (!servo_targets_.empty()) update_servo_targets();
  auto run = [&](std::size_t first, std::size_t last) {
    on_team(parallel_, [&] {
      for (std::size_t k = first; k < last; ++k) {
        run_stage(kPipeline[k]);
        if (timed && omp_get_thread_num() == 0) clock.end_stage(kPipeline[k]);
      }
    });
  };
  constexpr std::size_t pair_list = 1;
  static_assert(kPipeline[pair_list] == Stage::PairList);
  if (decomposed_) {
    // The decomposition's finder makes its own regions: its stage runs between two.
    run(0, pair_list);
    run_stage(Stage::PairList);
    if (timed) clock.end_stage(Stage::PairList);
    run(pair_list + 1, kPipeline.size());
  } else {
    run(0, kPipeline.size());
  }
  if (timed)
    clock.end_step();
  else if (clock.on)
    clock.count_untimed_step();
  if (clock.on) clock.add_step_wall(std::chrono::steady_clock::now() - start);
}

template <class Real>
void CpuSolver<Real>::run_stage(Stage stage) {
  // MPI ranks' split step (set_ghost_hooks): the ghosts arrive during the pair stages.
  const bool split = static_cast<bool>(take_ghosts_);
  switch (stage) {
    case Stage::Geometry: return update_geometry(split ? Part::Own : Part::All);
    case Stage::PairList:
      if (split) return split_pair_list();
      return keeps_lists_ ? kept_pair_list() : find_pairs();
    case Stage::PairForces:
      if (split)
        split_pair_forces();
      else
        compute_pair_forces();
      if (bonds() > 0) compute_bond_forces();
      return;
    case Stage::Gather:
      accumulate();
      if (bonds() > 0) add_bond_loads();
      if (n_bodies_ > 0) gather_bodies();
      return;
    case Stage::Check:
      if (n_bodies_ > 0)
        check_body_runaway();
      else
        check_runaway();
      if (check_hook_) team_master(check_hook_);
      return;
    case Stage::Integrate:
      if (bonds() > 0) commit_bonds();
      return n_bodies_ > 0 ? integrate_bodies() : integrate();
  }
}

template <class Real>
StageTimes CpuSolver<Real>::stage_times() const {
  return stopwatch_.times();
}

template <class Real>
void CpuSolver<Real>::update_geometry(Part part) {
  const auto n = static_cast<std::int64_t>(n_);
  const std::uint8_t* received = part == Part::All ? nullptr : received_.data();
  const bool ghosts = part == Part::Ghosts;
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (received && (received[i] != 0) != ghosts) continue;
    Vec2<Real> body_frame[3];
    physics::load_vertices(offset_x_, offset_y_, i, body_frame);
    const physics::PlacedBody<Real> placed =
        physics::place_body(Vec2d{x_[i], y_[i]}, theta_[i], body_frame, half_size_[i]);
    physics::store_vertices(rel_x_, rel_y_, i, placed.rel);
    lo_x_[i] = placed.box.lo.x;
    lo_y_[i] = placed.box.lo.y;
    hi_x_[i] = placed.box.hi.x;
    hi_y_[i] = placed.box.hi.y;
    PartnerRecord<Real>& r = partner_[i];
    r.x = x_[i];
    r.y = y_[i];
    r.vx = vx_[i];
    r.vy = vy_[i];
    r.w = w_[i];
    for (int k = 0; k < 3; ++k) {
      r.rel_x[k] = placed.rel[k].x;
      r.rel_y[k] = placed.rel[k].y;
    }
    r.lo_x = placed.box.lo.x;
    r.lo_y = placed.box.lo.y;
    r.hi_x = placed.box.hi.x;
    r.hi_y = placed.box.hi.y;
    r.area = area_[i];
    r.mass = mass_[i];
    r.material = material_[i];
  }
}

template <class Real>
void CpuSolver<Real>::find_pairs() {
  const TriangleArrays<Real> geometry{{rel_x_[0].data(), rel_x_[1].data(), rel_x_[2].data()},
                                      {rel_y_[0].data(), rel_y_[1].data(), rel_y_[2].data()},
                                      lo_x_.data(), lo_y_.data(), hi_x_.data(), hi_y_.data(),
                                      x_.data(), y_.data()};
  // The frame of this step, in a periodic cell: each method sees partners at their
  // nearest images through it.
  const physics::PeriodicFrame frame =
      periodic_ ? frame_at(static_cast<double>(step_) * dt_) : physics::PeriodicFrame{};
  const physics::PeriodicFrame* through = periodic_ ? &frame : nullptr;
  if (method_ == Method::SingleDomain) {
    single_domain_.find(geometry, parallel_, pairs_, through);
  } else if (decomposed_)
    decomposed_->find(x_.data(), y_.data(), geometry, parallel_, pairs_, through);
  else if (periodic_) {
    const PeriodicView view{frame, x_.data(), y_.data()};
    finder_.find({lo_x_.data(), lo_y_.data(), hi_x_.data(), hi_y_.data()}, method_, parallel_,
                 pairs_, &view);
  } else {
    finder_.find({lo_x_.data(), lo_y_.data(), hi_x_.data(), hi_y_.data()}, method_, parallel_,
                 pairs_);
  }
  finish_pair_list();
}

template <class Real>
void CpuSolver<Real>::finish_pair_list() {
  team_single([&] {
    grow_to(slip_, pairs_.count());
    grow_to(result_, pairs_.count());
  });
  build_reverse_index(pairs_, n_, parallel_, reverse_);
}

template <class Real>
physics::Body<Real> CpuSolver<Real>::body(std::int32_t i, Vec2d origin) const {
  const PartnerRecord<Real>& r = partner_[i];
  return r.body(physics::offset_from<Real>(origin, Vec2d{r.x, r.y}), Vec2d{r.vx, r.vy});
}

template <class Real>
physics::Body<Real> CpuSolver<Real>::image_body(std::int32_t i, Vec2d origin,
                                                const physics::PeriodicImage& im) const {
  const PartnerRecord<Real>& r = partner_[i];
  return r.body(physics::image_offset<Real>(origin, Vec2d{r.x, r.y}, im),
                Vec2d{r.vx + im.dvx, r.vy});
}

template <class Real>
physics::PeriodicFrame CpuSolver<Real>::frame_at(double t) const {
  return periodic_frame_of(cell_, t);
}

template <class Real>
void CpuSolver<Real>::compute_pair_forces() {
  compute_pair_slots(Part::All);
  report_too_deep();
}

// A slot's result depends on its own inputs only, and every sum over slots runs in a fixed
// order (pair_sums.hpp, row_energy.hpp): the passes of the split step, which compute the
// slots in another order, give the same bits.
template <class Real>
void CpuSolver<Real>::compute_pair_slots(Part part) {
  const auto n = static_cast<std::int64_t>(n_);
  // The lowest emitter with a pair deeper than the limit: a min over the threads, so the
  // same pair is reported whatever the threads.
  std::int64_t too_deep = kNoIndex;
  int ghost_contact = 0;
  const physics::PeriodicFrame frame =
      periodic_ ? frame_at(static_cast<double>(step_) * dt_) : physics::PeriodicFrame{};
  // A list built from build boxes may hold pairs whose boxes no longer overlap; the split
  // step's passes take the slots with or without a received particle.
  const std::uint8_t* received = received_.empty() ? nullptr : received_.data();
  const bool ghosts = part == Part::Ghosts, same_list = same_list_, grown = keeps_lists_;
  const bool polls = part == Part::Own && poll_ && omp_get_thread_num() == 0;
#pragma omp for schedule(dynamic, 256) nowait
  for (std::int64_t e = 0; e < n; ++e) {
    const auto emitter = static_cast<std::int32_t>(e);
    if (polls && e % 256 == 0) poll_();
    const bool received_e = received && received[e] != 0;
    if (part == Part::Own && received_e) continue;
    // The pass on ghosts: an own row without a received partner has nothing for it.
    if (ghosts && !received_e &&
        std::none_of(pairs_.partner.begin() + pairs_.offset[e],
                     pairs_.partner.begin() + pairs_.offset[e + 1],
                     [&](std::int32_t j) { return received[j] != 0; }))
      continue;
    OldRow<std::int64_t, physics::PairSlip<Real>> old{old_pairs_.partner.data(), old_slip_.data(),
                                                      old_pairs_.offset[e],
                                                      old_pairs_.offset[e + 1]};
    // The pair's frame: origin at the emitter's centroid (physics/local_frame.hpp).
    const Vec2d origin{x_[e], y_[e]};
    const physics::Body<Real> a = body(emitter, origin);
    const physics::Aabb<Real> box_e = physics::box_of(lo_x_[e], lo_y_[e], hi_x_[e], hi_y_[e]);
    const auto dt = static_cast<Real>(dt_);
    const std::int32_t* body_of = n_bodies_ > 0 ? member_body_.data() : nullptr;
    double image_power = 0;
    for (std::int64_t s = pairs_.offset[e]; s < pairs_.offset[e + 1]; ++s) {
      const std::int32_t j = pairs_.partner[s];
      const PartnerRecord<Real>& partner = partner_[j];
      const bool on_ghost = received && (received_e || received[j] != 0);
      if (part != Part::All && on_ghost != ghosts) continue;
      // Members of one body, and triangles an intact bond holds: exact zeros, no history;
      // so is a kept pair whose boxes no longer overlap, as if it were not listed.
      if (physics::same_body(body_of, e, j) || physics::intact_bond_between(bond_view_, e, j) ||
          (grown && !physics::boxes_overlap(box_e, physics::box_of(partner.lo_x, partner.lo_y,
                                                                   partner.hi_x, partner.hi_y)))) {
        result_[s] = physics::PairForce<Real>{};
        slip_[s] = physics::PairSlip<Real>{};
        continue;
      }
      // The last step's list, slot by slot: its slot's history is the pair's.
      physics::PairSlip<Real> slip = same_list ? old_slip_[s] : old.history_of(j);
      const auto& law = laws_[material_[emitter] * n_materials_ + partner.material];
      const auto force = [&](const physics::Body<Real>& b) {
        return pair_energy_ ? physics::SceneContactLaw::force<true>(a, b, law, dt, slip)
                            : physics::SceneContactLaw::force<false>(a, b, law, dt, slip);
      };
      if (periodic_) {
        const physics::PeriodicImage im =
            physics::nearest_image(frame, origin, {partner.x, partner.y});
        result_[s] = force(image_body(j, origin, im));
        image_power += physics::image_power(im, static_cast<double>(result_[s].force_a.x));
      } else {
        result_[s] = force(body(j, origin));
      }
      slip_[s] = slip;
      if (result_[s].depth > penetration_limit_) too_deep = std::min(too_deep, e);
      if (on_ghost && result_[s].touching) ghost_contact = 1;
    }
    if (!image_power_.empty()) image_power_[e] = image_power;
  }
  team_fold(too_deep_, too_deep, [](std::int64_t a, std::int64_t b) { return std::min(a, b); });
  if (received)
    team_fold(ghost_contact_, ghost_contact, [](int a, int b) { return std::max(a, b); });
}

template <class Real>
void CpuSolver<Real>::report_too_deep() {
  if (too_deep_ < static_cast<std::int64_t>(n_))
    team_single([&] { report_penetration(static_cast<std::int32_t>(too_deep_)); });
}

template <class Real>
void CpuSolver<Real>::set_ghost_hooks(std::vector<std::uint8_t> received,
                                      std::function<void()> take, std::function<void()> poll) {
  if (!can_take_ghosts_mid_step() || received.size() != n_)
    throw RunError("internal error: this solver cannot take its ghosts mid-step");
  received_ = std::move(received);
  take_ghosts_ = std::move(take);
  poll_ = std::move(poll);
  list_kept_ = false;  // the first split step builds its list
}

// The PairList stage on the grid without a periodic cell, with a skin (keeps_lists_): the
// last step's list when no box has left its build box, else a list built from the boxes
// grown by the skin. The same pairs get forces as from a list built every step, with the
// same bits (a kept pair whose boxes do not overlap gets an unlisted pair's zeros, rows stay
// sorted by partner), for a list built every few steps and each pair's history by slot.
template <class Real>
void CpuSolver<Real>::kept_pair_list() {
  if (may_keep_) test_build_boxes(Part::All);
  if (!may_keep_ || left_box_ != 0) return build_grown_list();
  keep_last_list();
}

// This step's list is the last step's: its slots, and its reverse index, which reverse_
// still holds.
template <class Real>
void CpuSolver<Real>::keep_last_list() {
  team_single([&] {
    same_list_ = true;
    pairs_.offset = old_pairs_.offset;
    grow_to(pairs_.partner, old_pairs_.count());
    std::copy(old_pairs_.partner.begin(), old_pairs_.partner.begin() + old_pairs_.count(),
              pairs_.partner.begin());
  });
}

// The split step (set_ghost_hooks), its PairList stage: the own particles' geometry is
// there (Geometry skipped the received ones). The list is kept when it was built with build
// boxes and no own box has left its build box; else the ghosts are needed now, to build it.
template <class Real>
void CpuSolver<Real>::split_pair_list() {
  if (may_keep_) test_build_boxes(Part::Own);
  if (!may_keep_ || left_box_ != 0) {
    take_ghosts();
    build_grown_list();
    return;
  }
  team_single([&] { ghosts_taken_ = false; });
  keep_last_list();
}

// The PairForces stage: on a kept list, the pairs of own particles while the ghosts are in
// flight, then the ghosts, then theirs; unless a ghost's box has left its build box, when
// the list is built again and every pair computed on it (the early ones thrown away).
template <class Real>
void CpuSolver<Real>::split_pair_forces() {
  if (ghosts_taken_) {
    compute_pair_slots(Part::All);
    return report_too_deep();
  }
  compute_pair_slots(Part::Own);
  take_ghosts();
  test_build_boxes(Part::Ghosts);
  if (left_box_ != 0) {
    team_single([&] {
      too_deep_ = kNoIndex;
      ghost_contact_ = 0;
      ++overlap_counts_.discarded;
    });
    build_grown_list();
    compute_pair_slots(Part::All);
  } else {
    compute_pair_slots(Part::Ghosts);
    team_single([&] { ++overlap_counts_.overlapped; });
  }
  report_too_deep();
}

// The received particles' State written (the hook), then their geometry.
template <class Real>
void CpuSolver<Real>::take_ghosts() {
  team_master(take_ghosts_);
  update_geometry(Part::Ghosts);
  team_single([&] { ghosts_taken_ = true; });
}

// The grid's list of the boxes grown by the skin (the build boxes), which holds every pair
// whose boxes overlap until some box leaves its build box. Not periodic
// (can_take_ghosts_mid_step): under shear the images move without their particles, which the
// build boxes do not see.
template <class Real>
void CpuSolver<Real>::build_grown_list() {
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    build_lo_x_[i] = lo_x_[i] - margin_;
    build_lo_y_[i] = lo_y_[i] - margin_;
    build_hi_x_[i] = hi_x_[i] + margin_;
    build_hi_y_[i] = hi_y_[i] + margin_;
  }
  finder_.find({build_lo_x_.data(), build_lo_y_.data(), build_hi_x_.data(), build_hi_y_.data()},
               method_, parallel_, pairs_);
  finish_pair_list();
  team_single([&] {
    same_list_ = false;
    ++overlap_counts_.rebuilt;
    ++list_builds_;
  });
}

// Whether a box of `part` has left its build box (a non-finite one has), into left_box_.
template <class Real>
void CpuSolver<Real>::test_build_boxes(Part part) {
  const auto n = static_cast<std::int64_t>(n_);
  const bool ghosts = part == Part::Ghosts;
  int left = 0;
#pragma omp for schedule(static) nowait
  for (std::int64_t i = 0; i < n; ++i) {
    if (part != Part::All && (received_[i] != 0) != ghosts) continue;
    if (!(lo_x_[i] >= build_lo_x_[i] && lo_y_[i] >= build_lo_y_[i] && hi_x_[i] <= build_hi_x_[i] &&
          hi_y_[i] <= build_hi_y_[i]))
      left = 1;
  }
  team_fold(left_box_, left, [](int a, int b) { return std::max(a, b); });
}

// One thread per bond, each writing its own slot: OpenMP equals serial. The bond's frame:
// origin at a's centroid, as for a pair (physics/local_frame.hpp), b at its nearest image.
template <class Real>
void CpuSolver<Real>::compute_bond_forces() {
  const auto nb = static_cast<std::int64_t>(bonds());
  const physics::PeriodicFrame frame =
      periodic_ ? frame_at(static_cast<double>(step_) * dt_) : physics::PeriodicFrame{};
  const physics::BondArrays<Real> v = bond_view_;
#pragma omp for schedule(static)
  for (std::int64_t k = 0; k < nb; ++k) {
    const std::int32_t a = v.a[k], b = v.b[k];
    const Vec2d origin{x_[a], y_[a]}, cb{x_[b], y_[b]};
    v.result[k] = physics::step_bond(
        v, k, physics::image_offset<Real>(origin, cb, physics::nearest_image(frame, origin, cb)),
        theta_[a], theta_[b]);
  }
}

// After its pairs, each particle adds its bonds' loads (physics::add_bond_loads' order).
template <class Real>
void CpuSolver<Real>::add_bond_loads() {
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp for schedule(static)
  for (std::int64_t p = 0; p < n; ++p) {
    Vec2<Real> f{fx_[p], fy_[p]};
    Real t = torque_[p];
    physics::add_bond_loads(bond_view_, p, f, t);
    fx_[p] = f.x;
    fy_[p] = f.y;
    torque_[p] = t;
  }
}

template <class Real>
void CpuSolver<Real>::commit_bonds() {
  const auto nb = static_cast<std::int64_t>(bonds());
#pragma omp for schedule(static)
  for (std::int64_t k = 0; k < nb; ++k) physics::commit_bond(bond_view_, k);
}

template <class Real>
void CpuSolver<Real>::report_penetration(std::int32_t emitter) const {
  std::int64_t s = pairs_.offset[emitter];
  while (!(result_[s].depth > penetration_limit_)) ++s;
  const std::int32_t j = pairs_.partner[s];
  const DeepPair pair{shown_ids_.of_particle(emitter),      shown_ids_.of_particle(j),
                      static_cast<double>(x_[emitter]),     static_cast<double>(y_[emitter]),
                      static_cast<double>(x_[j]),           static_cast<double>(y_[j]),
                      static_cast<double>(result_[s].depth)};
  throw RunError(penetration_message(step_ + 1, pair, static_cast<double>(penetration_limit_),
                                     static_cast<double>(dt_), limit_));
}

template <class Real>
void CpuSolver<Real>::accumulate() {
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp for schedule(static)
  for (std::int64_t p = 0; p < n; ++p) {
    Vec2<Real> f;
    Real t;
    sum_pair_forces(p, pairs_.offset.data(), reverse_.offset.data(), reverse_.slot.data(),
                    result_.data(), f, t);
    fx_[p] = f.x;
    fy_[p] = f.y;
    torque_[p] = t;
  }
}

template <class Real>
physics::Pose<double> CpuSolver<Real>::advanced_pose(std::size_t i) const {
  return physics::stepped_or_programmed_pose(
      program_table(), program_[i], physics::time_after_step(step_, dt_), pose(i),
      motion_[i] == Motion::Free, Vec2<Real>{fx_[i], fy_[i]}, torque_[i], inv_mass_[i],
      inv_inertia_[i], gravity_, local_damping_, dt_);
}

// Check first, write second (integrate): a blow-up leaves the last good state in place.
// The lowest index among n moving things (particles or bodies) whose next pose runs away,
// n when none: the lowest, so that OpenMP reports what the serial solver reports.
template <class Real>
template <class IsFree, class Advanced, class HalfSize>
std::int64_t CpuSolver<Real>::first_runaway(std::int64_t n, IsFree is_free, Advanced advanced,
                                            HalfSize half_size) const {
  std::int64_t bad = kNoIndex;
#pragma omp for schedule(static) nowait
  for (std::int64_t i = 0; i < n; ++i) {
    if (!is_free(i)) continue;
    const physics::Pose<double> p = advanced(static_cast<std::size_t>(i));
    if (physics::runaway_step(p, half_size(i), dt_)) bad = std::min(bad, i);
  }
  team_fold(first_runaway_, bad, [](std::int64_t a, std::int64_t b) { return std::min(a, b); });
  return std::min(first_runaway_, n);
}

template <class Real>
void CpuSolver<Real>::check_runaway() const {
  const auto n = static_cast<std::int64_t>(n_);
  const std::int64_t bad = first_runaway(
      n, [this](std::int64_t i) { return motion_[i] == Motion::Free; },
      [this](std::size_t i) { return advanced_pose(i); },
      [this](std::int64_t i) { return static_cast<double>(half_size_[i]); });
  if (bad < n)
    team_single([&] {
      const auto i = static_cast<std::size_t>(bad);
      const physics::Pose<double> p = advanced_pose(i);
      throw RunError(runaway_message(step_ + 1, shown_ids_.of_particle(bad), x_[i], y_[i],
                                     norm(p.v), dt_, limit_));
    });
}

template <class Real>
void CpuSolver<Real>::integrate() {
  const auto n = static_cast<std::int64_t>(n_);
  const physics::PeriodicFrame frame =
      periodic_ ? frame_at(physics::time_after_step(step_, dt_)) : physics::PeriodicFrame{};
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    physics::Pose<double> p = advanced_pose(static_cast<std::size_t>(i));
    add_step_energy(static_cast<std::size_t>(i), pose(static_cast<std::size_t>(i)), p,
                    motion_[i] == Motion::Free);
    if (periodic_ && motion_[i] == Motion::Free)
      wrap(frame, p, inv_mass_[i], static_cast<std::size_t>(i));
    x_[i] = p.c.x;
    y_[i] = p.c.y;
    theta_[i] = p.theta;
    // A wall's velocity is read by add_step_energy from other threads: a programmed
    // wall's is written after this loop (write_program_velocities).
    if (motion_[i] != Motion::Free) continue;
    vx_[i] = p.v.x;
    vy_[i] = p.v.y;
    w_[i] = p.w;
  }
  if (!programs_.empty()) write_program_velocities();
}

// The programmed walls' new velocities, once every row's energy has read the old ones: the
// program's velocity at the step's end (a servo's from this step's force on the wall).
template <class Real>
void CpuSolver<Real>::write_program_velocities() {
  const auto n = static_cast<std::int64_t>(n_);
  const physics::ProgramTable table = program_table();
  const double t_new = physics::time_after_step(step_, dt_);
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (program_[i] < 0) continue;
    Vec2d v;
    double w = 0;
    physics::program_velocity(table, program_[i], t_new,
                              Vec2d{static_cast<double>(fx_[i]), static_cast<double>(fy_[i])}, v,
                              w);
    vx_[i] = v.x;
    vy_[i] = v.y;
    w_[i] = w;
  }
}

// The targets of the servos that follow a length, from the walls' poses at the step's
// start (bodies' in a scene with bodies): before the Check and Integrate stages read them.
// A handful of programs: serial.
template <class Real>
void CpuSolver<Real>::update_servo_targets() {
  const double* x = n_bodies_ > 0 ? body_x_.data() : x_.data();
  const double* y = n_bodies_ > 0 ? body_y_.data() : y_.data();
  for (std::size_t k = 0; k < programs_.size(); ++k)
    if (physics::follows_length(programs_[k]))
      servo_targets_[k] = physics::servo_target_at(programs_[k], x, y);
}

// Called for every particle as its step is written: the pairs of its own row (each pair is
// in one row) and, for a free particle, what local damping took from it.
template <class Real>
void CpuSolver<Real>::add_step_energy(std::size_t i, const physics::Pose<double>& before,
                                      const physics::Pose<double>& after, bool free) {
  auto wall_velocity = [this](std::int64_t j, Vec2d& v, double& w) {
    if (!walls_move_ || motion_[j] == Motion::Free) return false;
    v = {vx_[j], vy_[j]};
    w = w_[j];
    return true;
  };
  tridem::add_step_energy(energy_, static_cast<std::int64_t>(i), pairs_.offset.data(),
                          pairs_.partner.data(), result_.data(), wall_velocity, free, before, after,
                          Vec2<Real>{fx_[i], fy_[i]}, torque_[i], inv_mass_[i], inv_inertia_[i],
                          gravity_, local_damping_, dt_);
  if (!image_power_.empty()) energy_[kWallWork][i] += image_power_[i] * dt_;
}

template <class Real>
void CpuSolver<Real>::wrap(const physics::PeriodicFrame& frame, physics::Pose<double>& p,
                           double inv_mass, std::size_t booked) {
  energy_[kWallWork][booked] += physics::wrap_with_work(frame, p, inv_mass, gravity_);
}

// Each body sums its members' loads in ascending member order: OpenMP equals serial.
template <class Real>
void CpuSolver<Real>::gather_bodies() {
  const auto nb = static_cast<std::int64_t>(n_bodies_);
#pragma omp for schedule(static)
  for (std::int64_t b = 0; b < nb; ++b) {
    Vec2d f{};
    double t = 0;
    for (std::int64_t i = body_first_[b]; i < body_last_[b]; ++i)
      physics::add_member_load(f, t, Vec2<Real>{fx_[i], fy_[i]}, torque_[i],
                               Vec2d{x_[i] - body_x_[b], y_[i] - body_y_[b]});
    body_fx_[b] = f.x;
    body_fy_[b] = f.y;
    body_torque_[b] = t;
  }
}

template <class Real>
physics::Pose<double> CpuSolver<Real>::advanced_body_pose(std::size_t b) const {
  return physics::stepped_or_programmed_pose(
      program_table(), body_program_[b], physics::time_after_step(step_, dt_), body_pose(b),
      body_motion_[b] == Motion::Free, Vec2d{body_fx_[b], body_fy_[b]}, body_torque_[b],
      body_inv_mass_[b], body_inv_inertia_[b], gravity_, local_damping_, dt_);
}

template <class Real>
void CpuSolver<Real>::check_body_runaway() const {
  const auto nb = static_cast<std::int64_t>(n_bodies_);
  const std::int64_t bad = first_runaway(
      nb, [this](std::int64_t b) { return body_motion_[b] == Motion::Free; },
      [this](std::size_t b) { return advanced_body_pose(b); },
      [this](std::int64_t b) { return body_half_size_[b]; });
  if (bad < nb)
    team_single([&] {
      const auto b = static_cast<std::size_t>(bad);
      const physics::Pose<double> p = advanced_body_pose(b);
      throw RunError("body id " + std::to_string(shown_ids_.of_body(bad)) + ": " +
                     runaway_message(step_ + 1, shown_ids_.of_particle(body_first_[b]), body_x_[b],
                                     body_y_[b], norm(p.v), dt_, limit_));
    });
}

// Two loops: every body's step (its members' rows of energy read the walls' member
// velocities, which the second loop rewrites), then every member placed on its body.
template <class Real>
void CpuSolver<Real>::integrate_bodies() {
  const auto nb = static_cast<std::int64_t>(n_bodies_);
  const physics::PeriodicFrame frame =
      periodic_ ? frame_at(physics::time_after_step(step_, dt_)) : physics::PeriodicFrame{};
#pragma omp for schedule(static)
  for (std::int64_t b = 0; b < nb; ++b) {
    const auto ub = static_cast<std::size_t>(b);
    const physics::Pose<double> before = body_pose(ub);
    physics::Pose<double> after = advanced_body_pose(ub);
    const bool free = body_motion_[b] == Motion::Free;
    for (std::int64_t i = body_first_[b]; i < body_last_[b]; ++i)
      add_step_energy(static_cast<std::size_t>(i), before, after, false);
    if (free && local_damping_ > 0)  // the body's, booked on its first member
      energy_[kDissipatedLocal][static_cast<std::size_t>(body_first_[b])] +=
          physics::local_damping_dissipation(before, after, Vec2d{body_fx_[b], body_fy_[b]},
                                             body_torque_[b], body_inv_mass_[b],
                                             body_inv_inertia_[b], gravity_, local_damping_, dt_);
    // The members follow their wrapped body (place_members), so a body is never cut.
    if (periodic_ && free)
      wrap(frame, after, body_inv_mass_[b], static_cast<std::size_t>(body_first_[b]));
    body_x_[b] = after.c.x;
    body_y_[b] = after.c.y;
    body_theta_[b] = after.theta;
    // Only the members' velocities are read across threads (rows' energy), and they are
    // written by place_members, after this loop.
    if (!free && body_program_[b] < 0) continue;
    body_vx_[b] = after.v.x;
    body_vy_[b] = after.v.y;
    body_w_[b] = after.w;
  }
  place_members();
}

template <class Real>
void CpuSolver<Real>::place_members() {
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto b = static_cast<std::size_t>(member_body_[i]);
    const physics::Pose<double> p =
        physics::member_pose(body_pose(b), Vec2d{member_dx_[i], member_dy_[i]});
    x_[i] = p.c.x;
    y_[i] = p.c.y;
    theta_[i] = p.theta;
    vx_[i] = p.v.x;
    vy_[i] = p.v.y;
    w_[i] = p.w;
  }
}

template <class Real>
EnergyBudget CpuSolver<Real>::energy() const {
  EnergyBudget b;
  // The pairs of the last step are in old_pairs_ after the swap at the end of the step.
  if (step_ > 0)
    for (std::int64_t s = 0; s < old_pairs_.count(); ++s)
      b.elastic += static_cast<double>(result_[s].elastic_energy);
  for (std::size_t i = 0; i < n_; ++i) {
    b.dissipated_damping += energy_[kDissipatedDamping][i];
    b.dissipated_friction += energy_[kDissipatedFriction][i];
    b.dissipated_local += energy_[kDissipatedLocal][i];
    b.wall_work += energy_[kWallWork][i];
  }
  if (step_ > 0)
    for (std::size_t k = 0; k < bonds(); ++k)
      b.elastic += static_cast<double>(bonds_.result[k].elastic);
  for (double d : bonds_.dissipated) b.dissipated_fracture += d;
  return b;
}

template <class Real>
void CpuSolver<Real>::snapshot(Snapshot& out, bool with_contacts) const {
  out.step = step_;
  out.time = time_;
  out.resize(n_);
  copy_shown_fields(out, *this);
  fill_from_model(out, *this);
  fill_bodies(out, *this, n_bodies_);
  fill_bonds(out, bonds_);
  out.periodic = cell_;
  out.contacts.clear();
  out.contact_precision = kPrecisionOf<Real>;
  if (!with_contacts || step_ == 0) return;
  // The pairs of the last step are in old_pairs_ after the swap at the end of the step.
  append_contacts(out, n_, old_pairs_.offset.data(), old_pairs_.partner.data(), result_.data(),
                  x_.data(), y_.data());
  if (periodic_)
    set_image_shifts(out, frame_at(static_cast<double>(step_) * dt_), x_.data(), y_.data());
}

template class CpuSolver<float>;
template class CpuSolver<double>;

}  // namespace tridem
