#include "core/time_step.hpp"

#include "core/bond_model.hpp"

#include "physics/contact_laws.hpp"
#include "physics/geometry.hpp"
#include "physics/stability.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <omp.h>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace tridem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// True when triangle i is a member of a body of several triangles.
bool multi_member(const ParticleModel& model, std::size_t i) {
  const BodyModel& b = model.bodies;
  if (b.empty()) return false;
  const auto k = static_cast<std::size_t>(b.body[i]);
  return b.first[k + 1] - b.first[k] > 1;
}

/// The thinnest triangle of one kind of partner (free, or fixed and prescribed) and one
/// material: the stiffest target of that kind.
struct Thinnest {
  double height = kInf;
  std::int64_t id = -1;
  std::int64_t count = 0;
  double heaviest = 0;  ///< largest mass (0 for walls: they move by prescription)
};

/// Who sets the limit among the partners an edge can meet.
struct Setter {
  double strongest = 0;
  const Thinnest* partner = nullptr;
  bool partner_free = true;
  double zeta_max = 0;
};

/// Springs and dashpots per metre on an edge.
struct EdgeLoad {
  double kn = 0, kt = 0, cn = 0, ct = 0;
};

/// The stiffest load the scene's partners of each kind and material put on an edge of
/// length l of triangle i, pressed along its whole length, when i moves with mass m (its
/// own, or its body's) and is h_i high over that edge (at least).
EdgeLoad edge_load(const ParticleModel& model, std::size_t i, double l, double h_i, double m,
                   const std::vector<Thinnest> (&thinnest)[2],
                   const std::vector<physics::LawParameters<double>>& laws, Setter& who) {
  const std::size_t n_mat = thinnest[0].size();
  EdgeLoad load;
  for (int kind = 0; kind < 2; ++kind)
    for (std::size_t b = 0; b < n_mat; ++b) {
      const Thinnest& t = thinnest[kind][b];
      // The free kind includes the particle itself: a particle alone is bounded as if it
      // met a copy of itself, which keeps the automatic step defined.
      if (t.count == 0) continue;
      // What the contact law puts on an edge pressed by this partner, per metre.
      const physics::EdgeStiffness<double> in = physics::SceneContactLaw::edge_stiffness(
          laws[model.material[i] * n_mat + b], t.height, h_i);
      const double per_metre = in.normal;
      // Two free bodies: (u_a − u_b)² <= 2u_a² + 2u_b², so each takes twice the pair's
      // springs; a wall does not move.
      const double share = kind == 0 ? 2.0 : 1.0;
      const double m_eff = kind == 0 ? m * t.heaviest / (m + t.heaviest) : m;
      if (share * per_metre > who.strongest) {
        who.strongest = share * per_metre;
        who.partner = &t;
        who.partner_free = kind == 0;
      }
      who.zeta_max = std::max(who.zeta_max, in.damping_ratio);
      load.kn = std::max(load.kn, share * per_metre);
      load.kt = std::max(load.kt, share * per_metre * in.tangential_ratio);
      // Partners side by side along the edge, each at least as wide as its smallest
      // height (and no more than there are): n of them, each with its own dashpot
      // 2ζ√(m_eff·k), carry Σ√k <= √(n·Σk) of damping. m_eff grows with the partner's
      // mass: the heaviest one of this kind, or a wall's m.
      const double partners =
          std::min(1.0 + std::floor(l / t.height), static_cast<double>(t.count));
      auto dashpot = [&](double k) {
        return share * 2.0 * in.damping_ratio * std::sqrt(partners * m_eff * k * l) / l;
      };
      load.cn = std::max(load.cn, dashpot(per_metre));
      load.ct = std::max(load.ct, dashpot(per_metre * in.tangential_ratio));
    }
  return load;
}

/// The limit of a free particle or body with the springs and dashpots of its edges.
struct ParticleLimit {
  double dt = kInf;
  StepLimit limit;
};

ParticleLimit mode_limit(const physics::Sym3<double>& springs,
                         const physics::Sym3<double>& dashpots, double mass, double inertia,
                         double local, const Setter& who) {
  if (who.partner == nullptr) return {};  // nothing to meet
  const double lambda_k = local * physics::largest_mode(springs, mass, inertia);
  const double lambda_c = local * physics::largest_mode(dashpots, mass, inertia);
  ParticleLimit out;
  out.dt = physics::symplectic_euler_limit(lambda_k, lambda_c);
  out.limit.partner = who.partner->id;
  out.limit.partner_free = who.partner_free;
  out.limit.partner_height = who.partner->height;
  out.limit.damping_ratio = who.zeta_max;
  return out;
}

/// The limit of free particle i with every edge pressed along its whole length by the
/// stiffest partners of each kind and material, and the partner that sets it.
ParticleLimit particle_limit(const ParticleModel& model, std::size_t i,
                             const std::vector<Thinnest> (&thinnest)[2],
                             const std::vector<physics::LawParameters<double>>& laws,
                             double local) {
  const auto& r = model.offsets[i];
  physics::Sym3<double> springs, dashpots;
  Setter who;
  for (int e = 0; e < 3; ++e) {
    const Vec2d a = r[e], b = r[(e + 1) % 3];
    const EdgeLoad in = edge_load(model, i, norm(b - a), model.smallest_height[i], model.mass[i],
                                  thinnest, laws, who);
    physics::add_edge_springs(springs, a, b, in.kn, in.kt);
    physics::add_edge_springs(dashpots, a, b, in.cn, in.ct);
  }
  ParticleLimit out = mode_limit(springs, dashpots, model.mass[i], model.inertia[i], local, who);
  out.limit.particle = static_cast<std::int64_t>(i);
  out.limit.particle_height = model.smallest_height[i];
  return out;
}

/// For each edge of body b's members (3 per member, in member order), true when another
/// member has the same edge: inside the body, no partner can press on it. Matched on the
/// scene's exact coordinates; an edge shared only in part counts as outside, which can only
/// lower the bound.
std::vector<char> inner_edges(const Scene& scene, std::size_t first, std::size_t count) {
  using Point = std::pair<double, double>;
  struct Edge {
    Point lo, hi;
    std::size_t index;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * count);
  for (std::size_t m = 0; m < count; ++m)
    for (int e = 0; e < 3; ++e) {
      // In the model's vertex order (build_particle_model makes clockwise input CCW).
      physics::Triangle<double> t{{scene.triangles[first + m].vertices[0],
                                   scene.triangles[first + m].vertices[1],
                                   scene.triangles[first + m].vertices[2]}};
      if (physics::signed_area(t) < 0) std::swap(t.v[1], t.v[2]);
      Point a{t.v[e].x, t.v[e].y}, b{t.v[(e + 1) % 3].x, t.v[(e + 1) % 3].y};
      if (b < a) std::swap(a, b);
      edges.push_back({a, b, 3 * m + e});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
  });
  std::vector<char> inner(3 * count, 0);
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    if (edges[k].lo == edges[k + 1].lo && edges[k].hi == edges[k + 1].hi)
      inner[edges[k].index] = inner[edges[k + 1].index] = 1;
  return inner;
}

/// inner_edges of every body of several members, for every triangle (none for the others).
std::vector<char> all_inner_edges(const Scene& scene, const ParticleModel& model) {
  std::vector<char> inner(3 * model.size(), 0);
  const BodyModel& bodies = model.bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto first = static_cast<std::size_t>(bodies.first[b]);
    const auto count = static_cast<std::size_t>(bodies.first[b + 1]) - first;
    if (count < 2) continue;
    const std::vector<char> mine = inner_edges(scene, first, count);
    std::copy(mine.begin(), mine.end(), inner.begin() + static_cast<std::ptrdiff_t>(3 * first));
  }
  return inner;
}

/// The least height of triangle i over an edge a partner can press: its smallest height,
/// or for a body's member the least over its outer edges (infinite when it has none).
double outer_height(const ParticleModel& model, const std::vector<char>& inner, std::size_t i) {
  if (!multi_member(model, i)) return model.smallest_height[i];
  double h = kInf;
  const auto& r = model.offsets[i];
  for (int e = 0; e < 3; ++e)
    if (inner[3 * i + e] == 0) h = std::min(h, 2 * model.area[i] / norm(r[(e + 1) % 3] - r[e]));
  return h;
}

/// The limit of free body b of several members: the springs and dashpots of its members'
/// outer edges, about the body's centroid, on its mass and inertia.
ParticleLimit body_limit(const ParticleModel& model, const std::vector<char>& all_inner,
                         std::size_t b, const std::vector<Thinnest> (&thinnest)[2],
                         const std::vector<physics::LawParameters<double>>& laws, double local) {
  const BodyModel& bodies = model.bodies;
  const auto first = static_cast<std::size_t>(bodies.first[b]);
  const auto count = static_cast<std::size_t>(bodies.first[b + 1]) - first;
  const char* inner = all_inner.data() + 3 * first;
  const double mass = bodies.mass[b];
  physics::Sym3<double> springs, dashpots;
  Setter who;
  double thinnest_member = kInf;
  std::size_t thinnest_id = first;
  for (std::size_t m = 0; m < count; ++m) {
    const std::size_t i = first + m;
    const double height = outer_height(model, all_inner, i);
    if (height < thinnest_member) {
      thinnest_member = height;
      thinnest_id = i;
    }
    const auto& r = model.offsets[i];
    for (int e = 0; e < 3; ++e) {
      if (inner[3 * m + e] != 0) continue;
      const Vec2d a = bodies.member_offset[i] + r[e];
      const Vec2d c = bodies.member_offset[i] + r[(e + 1) % 3];
      // To first order a partner pressed on this edge sits in the member's sub-triangle
      // of this edge: the member's height over it is what counts, not its smallest.
      const double length = norm(c - a);
      const EdgeLoad in =
          edge_load(model, i, length, 2 * model.area[i] / length, mass, thinnest, laws, who);
      physics::add_edge_springs(springs, a, c, in.kn, in.kt);
      physics::add_edge_springs(dashpots, a, c, in.cn, in.ct);
    }
  }
  ParticleLimit out = mode_limit(springs, dashpots, mass, bodies.inertia[b], local, who);
  out.limit.particle = static_cast<std::int64_t>(thinnest_id);
  out.limit.body = static_cast<std::int64_t>(b);
  out.limit.body_members = static_cast<std::int64_t>(count);
  out.limit.particle_height = thinnest_member;
  return out;
}

}  // namespace

std::string StepLimit::describe() const {
  if (bonds)
    return "the cohesive bonds' springs (k = E/h: a finer mesh or a stiffer material "
           "needs a smaller step)";
  if (particle < 0) return "";
  const std::string who =
      body < 0 ? fmt::format("particle {} pressed on every edge", particle)
               : fmt::format("body {} ({} triangles, the thinnest particle {}) pressed on "
                             "every outer edge",
                             body, body_members, particle);
  if (partner_free)
    return fmt::format("{} by free particles as thin as particle {} ({:g} m)", who, partner,
                       partner_height);
  return fmt::format("{} by fixed or prescribed particle {} ({:g} m thick{})", who, partner,
                     partner_height, thin_wall() ? ": a thin wall makes a stiff contact" : "");
}

std::string TimeStep::describe() const {
  const std::string by = limit.describe();
  return fmt::format("dt_crit = {:g} s{}{}", critical, by.empty() ? "" : ", set by ", by);
}

std::string TimeStep::cure() const {
  return fmt::format(
      "lower dt or [simulation] safety{}",
      limit.thin_wall()
          ? fmt::format(", or make the thin wall (particle {}) thicker", limit.partner)
          : "");
}

TimeStep estimate_time_step(const Scene& scene, const ParticleModel& model) {
  const std::size_t n_mat = scene.materials.size();
  // thinnest[kind][material], kind 0: free, 1: fixed or prescribed.
  std::vector<Thinnest> thinnest[2] = {std::vector<Thinnest>(n_mat), std::vector<Thinnest>(n_mat)};
  // Edges inside a body: no partner reaches them.
  const std::vector<char> inner = all_inner_edges(scene, model);
  for (std::size_t i = 0; i < model.size(); ++i) {
    Thinnest& t = thinnest[model.motion[i] == Motion::Free ? 0 : 1][model.material[i]];
    const double height = outer_height(model, inner, i);
    if (!std::isfinite(height)) continue;  // a member inside its body touches nothing
    ++t.count;
    // A member moves with its body's mass: the heavier partner, the stronger a dashpot.
    const double mass =
        multi_member(model, i) ? model.bodies.mass[model.bodies.body[i]] : model.mass[i];
    if (model.motion[i] == Motion::Free) t.heaviest = std::max(t.heaviest, mass);
    if (height < t.height) {
      t.height = height;
      t.id = static_cast<std::int64_t>(i);
    }
  }
  const auto laws = contact_law_table(scene.materials);
  // Cundall's local damping turns a force F into F·(1 ± α): springs and dashpots at most
  // 1 + α times stiffer.
  const double local = 1.0 + scene.simulation.local_damping;

  TimeStep ts;
  ts.critical = kInf;
  auto keep = [&ts](const ParticleLimit& p) {
    if (p.dt < ts.critical) {
      ts.critical = p.dt;
      ts.limit = p.limit;
    }
  };
  // Each free particle's limit on the OpenMP threads (10^7 of them take seconds on one
  // core), each thread keeping its smallest; the threads' bests then go through keep in
  // thread order, which with static blocks is particle order: the first smallest wins, as
  // in one loop.
  const auto n = static_cast<std::int64_t>(model.size());
  std::vector<std::optional<ParticleLimit>> best(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel num_threads(static_cast <int>(best.size()))
  {
    std::optional<ParticleLimit>& mine = best[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      if (model.motion[i] != Motion::Free || multi_member(model, i)) continue;
      ParticleLimit p = particle_limit(model, i, thinnest, laws, local);
      if (!mine || p.dt < mine->dt) mine = p;
    }
  }
  for (const std::optional<ParticleLimit>& p : best)
    if (p) keep(*p);
  const BodyModel& bodies = model.bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies.motion[b] == Motion::Free && bodies.first[b + 1] - bodies.first[b] > 1)
      keep(body_limit(model, inner, b, thinnest, laws, local));
  // Bonds are springs of their own, as stiff as the material (k = E/h): their limit too.
  if (!scene.bonds.empty()) {
    const double bonds = bond_time_step_limit(model, build_bond_model(scene, model), local);
    if (bonds < ts.critical) {
      ts.critical = bonds;
      ts.limit = StepLimit{};
      ts.limit.bonds = true;
    }
  }
  ts.automatic = !scene.simulation.dt.has_value();
  if (!ts.automatic) {
    ts.chosen = *scene.simulation.dt;
  } else if (std::isfinite(ts.critical)) {
    ts.chosen = scene.simulation.safety * ts.critical;
  } else {
    throw SceneError(
        fmt::format("{}: [simulation] dt: no free particle to estimate a time step from; give dt",
                    scene.source));
  }
  return ts;
}

void check_time_step(const Scene& scene, const TimeStep& ts, bool force) {
  if (ts.automatic || force || ts.chosen <= ts.critical) return;
  throw RunError(fmt::format(
      "{}: [simulation] dt = {:g} s is above the stability limit {} (ratio {:.3g}); use "
      "dt <= {:g} (safety 0.1){}, leave dt out for an automatic step, or pass --force to run "
      "anyway",
      scene.source, ts.chosen, ts.describe(), ts.chosen / ts.critical, 0.1 * ts.critical,
      ts.limit.thin_wall()
          ? fmt::format(", make the thin wall (particle {}) thicker", ts.limit.partner)
          : ""));
}

}  // namespace tridem

namespace tridem {

std::int64_t steps_to_reach(const SimulationSettings& s, double dt) {
  if (s.duration <= 0) return s.steps;
  const double ratio = s.duration / dt;
  // 2^53: beyond it a step count is no longer exact in the time a run keeps.
  if (!(ratio < 9.007199254740992e15))
    throw RunError(fmt::format("[simulation] time = {} s is {:.3g} steps of dt = {:.6g} s, more "
                               "than a run can count: shorten the time or raise dt",
                               s.duration, ratio, dt));
  const double whole = std::round(ratio);
  const bool reached = std::abs(ratio - whole) <= 1e-9 * std::max(1.0, whole);
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(reached ? whole : std::ceil(ratio)));
}

}  // namespace tridem
