#pragma once
// The dashpot of a contact: c = 2ζ(n_eff)·√(m_eff·k) with k the contact's current
// stiffness. With a force F ∝ δ^n and this dashpot the restitution depends on ζ and n only,
// not on the impact speed (docs/model.md, "Damping"); ζ is calibrated per n on the host
// (restitution.hpp) and interpolated here.
#include "physics/body.hpp"

namespace tridem::physics {

/// Mass that sets the damping of a pair: the reduced mass, or the free body's mass when
/// the other is moved by prescription (mass 0).
template <class Real>
TRIDEM_HD inline Real effective_mass(Real ma, Real mb) {
  return (ma > Real(0) && mb > Real(0)) ? ma * mb / (ma + mb) : ma + mb;
}

/// ζ at load exponent n (clamped to [1, 2]), piecewise linear between the nodes.
template <class Real>
TRIDEM_HD inline Real damping_ratio(const ContactLaw<Real>& law, Real n) {
  const Real u = n <= Real(1) ? Real(0) : (n >= Real(2) ? Real(2) : Real(2) * (n - Real(1)));
  return u <= Real(1) ? law.damping[0] + u * (law.damping[1] - law.damping[0])
                      : law.damping[1] + (u - Real(1)) * (law.damping[2] - law.damping[1]);
}

/// The largest ζ the law uses at any contact shape: the bound a time-step estimate needs
/// (normal and tangential dashpots both use damping_ratio(law, n_eff) <= this).
template <class Real>
TRIDEM_HD inline Real max_damping_ratio(const ContactLaw<Real>& law) {
  Real z = law.damping[0];
  TRIDEM_UNROLL
  for (int i = 1; i < kDampingNodes; ++i) z = law.damping[i] > z ? law.damping[i] : z;
  return z;
}

}  // namespace tridem::physics
