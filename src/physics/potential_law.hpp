#pragma once
// The contact law tridem runs (Munjiza's potential with friction and damping, docs/model.md)
// as a contact-law policy: everything the rest of the code asks of a contact law, in one
// place. A contact law is a struct with these members; physics/contact_laws.hpp registers
// the one the solvers and the time step use.
//   Parameters<Real>     what a pair of materials needs: plain data, one table entry per
//                        pair of materials, copied to the GPU as it is
//   parameters(a, b)     host: the entry of materials a and b (the mixing rules)
//   cast<To>(p)          the entry in the pair precision
//   force<kEnergy>(a, b, p, dt, history)   TRIDEM_HD: the PairForce of one pair over a
//                        step, with its history (PairSlip) carried in and out; without
//                        kEnergy its elastic_energy is left at zero and the rest is the same
//   edge_stiffness(p, h_partner, h_own)   the contact's springs and dashpots along an edge
//                        pressed over its whole length, per metre: the time step's input
//                        (core/time_step.cpp bounds symplectic Euler with it)
#include "physics/contact_force.hpp"
#include "physics/damping.hpp"
#include "physics/restitution.hpp"
#include "tridem/scene.hpp"

#include <algorithm>
#include <map>
#include <mutex>

namespace tridem::physics {

/// Per metre of an edge pressed along its whole length by one partner: what the time-step
/// bound needs of a contact law.
template <class Real>
struct EdgeStiffness {
  Real normal;            ///< normal springs, N/m per metre of edge
  Real tangential_ratio;  ///< tangential springs / normal springs (0 without friction)
  Real damping_ratio;     ///< largest ζ of both dashpots, c = 2ζ√(m_eff·k)
};

struct PotentialLaw {
  template <class Real>
  using Parameters = ContactLaw<Real>;

  /// Penalties combine as springs in series (harmonic mean: p for equal materials); the
  /// smoother surface sets the friction; restitutions average, and the damping ratios are
  /// calibrated for the pair's restitution (docs/model.md, "Damping").
  static Parameters<double> parameters(const Material& a, const Material& b) {
    auto harmonic = [](double x, double y) { return 2.0 * x * y / (x + y); };
    return calibrated(harmonic(a.penalty, b.penalty),
                      harmonic(a.tangential_penalty, b.tangential_penalty),
                      std::min(a.friction, b.friction),
                      0.5 * (material_restitution(a.restitution, a.damping) +
                             material_restitution(b.restitution, b.damping)));
  }

  template <class To, class From>
  static Parameters<To> cast(const Parameters<From>& p) {
    return law_cast<To>(p);
  }

  template <bool kEnergy = true, class Real>
  TRIDEM_HD static PairForce<Real> force(const Body<Real>& a, const Body<Real>& b,
                                         const Parameters<Real>& law, Real dt,
                                         PairSlip<Real>& slip) {
    return pair_force<kEnergy>(a, b, law, dt, slip);
  }

  /// One pair pressed along a length ℓ of an edge: ℓ of that edge in the partner's
  /// sub-triangles (heights >= h_partner) and about ℓ of the partner's boundary in the
  /// particle's own (heights >= h_own): k = 3p·ℓ·(1/h_partner + 1/h_own), pair_force's
  /// stiffness bound (its normal dashpot uses k_N = N·K·N <= it). Tangential: the spring
  /// on the contact's tangent, k_t = (p_t/p)·k_n, inert without friction (capped at
  /// μ·f_n = 0). Damping: c = 2ζ(n_eff)·√(m_eff·k) on both springs, ζ(n_eff) <=
  /// max_damping_ratio(law).
  template <class Real>
  TRIDEM_HD static EdgeStiffness<Real> edge_stiffness(const Parameters<Real>& law,
                                                      Real h_partner, Real h_own) {
    const Real ratio =
        law.friction > Real(0) ? law.tangential_penalty / law.penalty : Real(0);
    return {Real(3) * law.penalty * (Real(1) / h_partner + Real(1) / h_own), ratio,
            max_damping_ratio(law)};
  }

 private:
  /// contact_law with the calibration of each restitution done once per process: solvers,
  /// the time-step estimate and scene descriptions all build the table, and the
  /// calibration integrates an ODE some thousand times.
  static Parameters<double> calibrated(double p, double pt, double mu, double e) {
    static std::mutex mutex;
    static std::map<double, Parameters<double>> known;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = known.find(e);
    if (it == known.end()) it = known.emplace(e, contact_law(1, 1, 0, e)).first;
    Parameters<double> law = it->second;
    law.penalty = p;
    law.tangential_penalty = pt;
    law.friction = mu;
    return law;
  }
};

}  // namespace tridem::physics
