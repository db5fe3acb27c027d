#pragma once
// Host-side calibration of the damping ratios that give a coefficient of restitution e.
//
// A contact with force F = K·δ^n, current stiffness k = dF/dδ = nK·δ^(n−1) and dashpot
// c = 2ζ√(m·k) obeys, in units where the approach speed and the contact scale are one,
//     y'' = −y^n − 2ζ·√n·y^((n−1)/2)·y',   y(0) = 0, y'(0) = 1,
// whatever the speed, mass and stiffness: the restitution e = −y'(t_sep) is a function of
// ζ and n alone. For n = 1 it is exp(−πζ/√(1−ζ²)); for other n it is found by integrating
// the equation (RK4), and ζ(e, n) by bisection (e falls monotonically with ζ).
// Not TRIDEM_HD: solvers build their ContactLaw tables once, on the host.
#include "physics/body.hpp"

#include <cmath>
#include <optional>

namespace tridem::physics {

/// Restitution of the nondimensional impact above.
inline double restitution_for(double zeta, double n) {
  if (zeta <= 0) return 1.0;
  const double h = 2e-3;  // a contact lasts about 3 to 4 time units
  auto accel = [&](double y, double v) {
    const double yp = y > 0 ? y : 0.0;
    return -std::pow(yp, n) - 2 * zeta * std::sqrt(n) * std::pow(yp, 0.5 * (n - 1)) * v;
  };
  double y = 0, v = 1;
  for (int step = 0; step < 20000; ++step) {  // t < 40: an overdamped contact does not return
    const double k1y = v, k1v = accel(y, v);
    const double k2y = v + 0.5 * h * k1v, k2v = accel(y + 0.5 * h * k1y, v + 0.5 * h * k1v);
    const double k3y = v + 0.5 * h * k2v, k3v = accel(y + 0.5 * h * k2y, v + 0.5 * h * k2v);
    const double k4y = v + h * k3v, k4v = accel(y + h * k3y, v + h * k3v);
    const double y1 = y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    const double v1 = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (y1 <= 0 && step > 0) {
      // Separation inside this step: the speed at y = 0, linearly between the ends.
      const double f = y / (y - y1);
      return -(v + f * (v1 - v));
    }
    y = y1;
    v = v1;
  }
  return 0.0;
}

/// ζ giving restitution e (0 < e <= 1) at load exponent n.
inline double damping_for_restitution(double e, double n) {
  if (e >= 1) return 0.0;
  if (n == 1.0) {
    const double l = std::log(e);
    return -l / std::sqrt(M_PI * M_PI + l * l);
  }
  double lo = 0, hi = 4;
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    (restitution_for(mid, n) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The restitution an old scene's damping ratio ζ stands for: that of a face contact
/// under the former constant-stiffness dashpot, exp(−πζ/√(1−ζ²)).
inline double restitution_of_damping_ratio(double zeta) {
  return std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta));
}

/// A material's coefficient of restitution: `restitution`, or the one its legacy damping
/// ratio stands for.
inline double material_restitution(const std::optional<double>& restitution, double damping) {
  return restitution ? *restitution : restitution_of_damping_ratio(damping);
}

/// A contact law with damping calibrated for restitution e at every contact shape.
inline ContactLaw<double> contact_law(double penalty, double tangential_penalty, double friction,
                                      double restitution) {
  ContactLaw<double> law{penalty, tangential_penalty, friction, {}};
  for (int i = 0; i < kDampingNodes; ++i)
    law.damping[i] = damping_for_restitution(restitution, 1.0 + 0.5 * i);
  return law;
}

}  // namespace tridem::physics
