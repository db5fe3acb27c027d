#include "core/time_step.hpp"

#include "core/bond_model.hpp"

#include "physics/contact_laws.hpp"
#include "physics/stability.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

namespace tridem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The thinnest triangle of one kind of partner (free, or fixed and prescribed) and one
/// material: the stiffest target of that kind.
struct Thinnest {
  double height = kInf;
  std::int64_t id = -1;
  std::int64_t count = 0;
  double heaviest = 0;  ///< largest mass (0 for walls: they move by prescription)
};

/// The limit of free particle i with every edge pressed along its whole length by the
/// stiffest partners of each kind and material, and the partner that sets it.
struct ParticleLimit {
  double dt = kInf;
  StepLimit limit;
};

ParticleLimit particle_limit(const ParticleModel& model, std::size_t i,
                             const std::vector<Thinnest> (&thinnest)[2],
                             const std::vector<physics::LawParameters<double>>& laws,
                             double local) {
  const std::size_t n_mat = thinnest[0].size();
  const double m = model.mass[i], h_i = model.smallest_height[i];
  const auto& r = model.offsets[i];
  double edge_length[3];
  for (int e = 0; e < 3; ++e) edge_length[e] = norm(r[(e + 1) % 3] - r[e]);
  // Per metre of each edge: normal and tangential stiffness, normal and tangential
  // damping, the largest over the partners this particle can meet.
  double kn[3] = {}, kt[3] = {}, cn[3] = {}, ct[3] = {};
  double strongest = 0;
  const Thinnest* setter = nullptr;
  bool setter_free = true;
  double zeta_max = 0;
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
      if (share * per_metre > strongest) {
        strongest = share * per_metre;
        setter = &t;
        setter_free = kind == 0;
      }
      zeta_max = std::max(zeta_max, in.damping_ratio);
      for (int e = 0; e < 3; ++e) {
        const double l = edge_length[e];
        kn[e] = std::max(kn[e], share * per_metre);
        kt[e] = std::max(kt[e], share * per_metre * in.tangential_ratio);
        // Partners side by side along the edge, each at least as wide as its smallest
        // height (and no more than there are): n of them, each with its own dashpot
        // 2ζ√(m_eff·k), carry Σ√k <= √(n·Σk) of damping. m_eff grows with the
        // partner's mass: the heaviest one of this kind, or a wall's m.
        const double partners =
            std::min(1.0 + std::floor(l / t.height), static_cast<double>(t.count));
        auto dashpot = [&](double k) {
          return share * 2.0 * in.damping_ratio * std::sqrt(partners * m_eff * k * l) / l;
        };
        cn[e] = std::max(cn[e], dashpot(per_metre));
        ct[e] = std::max(ct[e], dashpot(per_metre * in.tangential_ratio));
      }
    }
  if (setter == nullptr) return {};  // nothing to meet
  physics::Sym3<double> springs, dashpots;
  for (int e = 0; e < 3; ++e) {
    physics::add_edge_springs(springs, r[e], r[(e + 1) % 3], kn[e], kt[e]);
    physics::add_edge_springs(dashpots, r[e], r[(e + 1) % 3], cn[e], ct[e]);
  }
  const double lambda_k = local * physics::largest_mode(springs, m, model.inertia[i]);
  const double lambda_c = local * physics::largest_mode(dashpots, m, model.inertia[i]);
  const double dt = physics::symplectic_euler_limit(lambda_k, lambda_c);
  return {dt, {static_cast<std::int64_t>(i), setter->id, setter_free, setter->height, h_i,
               zeta_max}};
}

}  // namespace

std::string StepLimit::describe() const {
  if (bonds)
    return "the cohesive bonds' springs (k = E/h: a finer mesh or a stiffer material "
           "needs a smaller step)";
  if (particle < 0) return "";
  if (partner_free)
    return fmt::format("particle {} pressed on every edge by free particles as thin as "
                       "particle {} ({:g} m)",
                       particle, partner, partner_height);
  return fmt::format("particle {} pressed on every edge by fixed or prescribed particle {} "
                     "({:g} m thick{})",
                     particle, partner, partner_height,
                     thin_wall() ? ": a thin wall makes a stiff contact" : "");
}

std::string TimeStep::describe() const {
  const std::string by = limit.describe();
  return fmt::format("dt_crit = {:g} s{}{}", critical, by.empty() ? "" : ", set by ", by);
}

std::string TimeStep::cure() const {
  return fmt::format("lower dt or [simulation] safety{}",
                     limit.thin_wall()
                         ? fmt::format(", or make the thin wall (particle {}) thicker",
                                       limit.partner)
                         : "");
}

TimeStep estimate_time_step(const Scene& scene, const ParticleModel& model) {
  const std::size_t n_mat = scene.materials.size();
  // thinnest[kind][material], kind 0: free, 1: fixed or prescribed.
  std::vector<Thinnest> thinnest[2] = {std::vector<Thinnest>(n_mat),
                                       std::vector<Thinnest>(n_mat)};
  for (std::size_t i = 0; i < model.size(); ++i) {
    Thinnest& t = thinnest[model.motion[i] == Motion::Free ? 0 : 1][model.material[i]];
    ++t.count;
    if (model.motion[i] == Motion::Free) t.heaviest = std::max(t.heaviest, model.mass[i]);
    if (model.smallest_height[i] < t.height) {
      t.height = model.smallest_height[i];
      t.id = static_cast<std::int64_t>(i);
    }
  }
  const auto laws = contact_law_table(scene.materials);
  // Cundall's local damping turns a force F into F·(1 ± α): springs and dashpots at most
  // 1 + α times stiffer.
  const double local = 1.0 + scene.simulation.local_damping;

  TimeStep ts;
  ts.critical = kInf;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (model.motion[i] != Motion::Free) continue;
    const ParticleLimit p = particle_limit(model, i, thinnest, laws, local);
    if (p.dt < ts.critical) {
      ts.critical = p.dt;
      ts.limit = p.limit;
    }
  }
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
    throw SceneError(fmt::format(
        "{}: [simulation] dt: no free particle to estimate a time step from; give dt",
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
