#pragma once
// The notched beam of issue 14 (docs/fracture.md, "The notched beam"): a bonded granite beam
// with a notch under midspan, in three-point bending, and the measure of the crack it
// grows: its length (the broken bonds' edges, and their projection on the ligament), the
// energy its bonds released, and their mode mixity. Shared by the validation test and the
// docs' numbers.
#include "support/bonded_specimens.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tridem::test {

/// The beam: `span` between the supports' centres, length 1.25 span, `depth`; the notch
/// under midspan `notch_width` wide, its pointed tip at y = `notch_depth`; mesh `size`. The
/// nose's speed ramps from 0 to `speed` over `ramp` seconds (a nose that starts at full
/// speed strikes the beam, and the contact rings: the load then swings between 0 and
/// several times the beam's strength).
struct NotchedBeam {
  double span = 0.06, depth = 0.015, notch_depth = 0.0075, notch_width = 0.001;
  double size = 0.0015, speed = 0.2, ramp = 5e-5, damping = 0.2, safety = 0.6;
};

/// The supports and the nose: frictionless, as rollers are (a contact's friction is the
/// smaller of its two materials'). With the granite's friction 0.6 the supports hold the
/// halves of a cracked beam from sliding apart, and the halves and the ligament left under
/// the nose stand as a three-hinged arch that carries the load with the crack arrested.
constexpr std::string_view kRollerMaterial =
    "[[material]]\nname = \"roller\"\ndensity = 7800\npenalty = 5e10\nfriction = 0\n";

/// Supports (ids 0, 1: flat tops at y = 0, depth / 2 wide, centred on x = -+span/2), the
/// nose (id 2: its flat bottom as wide on y = depth over x = 0), then the beam's triangles.
inline Scene notched_beam_scene(const NotchedBeam& p) {
  const double s = 0.5 * p.span, b = 0.25 * p.depth, l = 1.25 * s, w = 0.5 * p.notch_width;
  const std::string toml =
      bonded_granite_header(p.damping, p.safety) + std::string(kRollerMaterial) +
      fmt::format(
          "[[triangle]]\nmaterial = \"roller\"\nvertices = [[{msb}, 0], [{ms}, {mb}], "
          "[{msb2}, 0]]\nfixed = true\n"
          "[[triangle]]\nmaterial = \"roller\"\nvertices = [[{sb}, 0], [{s}, {mb}], "
          "[{sb2}, 0]]\nfixed = true\n"
          "[[triangle]]\nmaterial = \"roller\"\nvertices = [[{mb}, {d}], [{b}, {d}], [0, {db}]]\n"
          "motion = \"prescribed\"\n"
          "program = {{ kind = \"table\", times = [0, {ramp}], velocities = [[0, 0], [0, {v}]] }}\n"
          "[[mesh]]\nkind = \"polygon\"\npolygon = [[{ml}, 0], [{mw}, 0], [{mw}, {aw}], [0, {a}], "
          "[{w}, {aw}], [{w}, 0], [{l}, 0], [{l}, {d}], [{ml}, {d}]]\nsize = {size}\n"
          "material = \"granite\"\nbonded = true\n",
          fmt::arg("s", s), fmt::arg("ms", -s), fmt::arg("b", b), fmt::arg("mb", -b),
          fmt::arg("msb", -s - b), fmt::arg("msb2", -s + b), fmt::arg("sb", s - b),
          fmt::arg("sb2", s + b), fmt::arg("d", p.depth), fmt::arg("db", p.depth + b),
          fmt::arg("ramp", p.ramp), fmt::arg("v", -p.speed), fmt::arg("l", l), fmt::arg("ml", -l),
          fmt::arg("w", w), fmt::arg("mw", -w), fmt::arg("a", p.notch_depth),
          fmt::arg("aw", p.notch_depth - w), fmt::arg("size", p.size));
  return parse_scene(toml, "notched_beam.toml");
}

/// The crack of a notched beam, from the bonds of its scene and a solver's state, by the
/// bonds' Gauss points: each carries half of its edge (physics/cohesive_bond.hpp), and one
/// fully damaged has released G L / 2, so a point with D = 1 is a piece of crack L / 2
/// long. Counted by points because the crack's last bond, at the beam's top face under the
/// nose, keeps its upper point: the beam's halves turn about it (a hinge: it neither opens
/// nor slides), so it never breaks. Crack points are those with D = 1 whose half-edge's
/// midpoint lies within `band` of the notch's line x = 0; D = 1 elsewhere (under the
/// supports or the nose) is counted apart, and so is the energy of bonds with no point
/// broken (the process zone left on either side of the crack, and its dead-end branches).
struct CrackMeasure {
  int crack_bonds = 0;   ///< bonds with a crack point
  int broken_bonds = 0;  ///< of which both points: broken for good
  int other_bonds = 0, damaged_bonds = 0;
  double path_length = 0;  ///< m: the crack points' half-edges, summed
  /// m: the union of the crack points' half-edges' extents in y, within the ligament
  /// [notch_depth, depth]: the crack's length projected on the ligament.
  double projected = 0;
  double ligament = 0;          ///< depth - notch_depth, m
  double crack_energy = 0;      ///< J/m released by the bonds with a crack point
  double other_energy = 0;      ///< J/m released by bonds broken away from the ligament
  double damaged_energy = 0;    ///< J/m released by bonds with no point broken
  double total_energy = 0;      ///< J/m: all the bonds (energy.csv's dissipated_fracture)
  double predicted_energy = 0;  ///< J/m: sum of G(theta) L / 2 over the crack points, theta
                                ///< the bond's normal's angle to the crack's opening, along x
  double mode2_share = 0;       ///< energy-weighted share of the broken bonds' in mode II
  double mean_abs_angle = 0;    ///< degrees: length-weighted mean |theta| of crack points
  double tortuosity() const { return projected > 0 ? path_length / projected : 0; }
};

/// G(theta) per unit length of a bond opened at theta to its normal, under the linear
/// mixed-mode criterion (physics/cohesive_bond.hpp; its unit test checks the formula).
inline double inclined_bond_energy(double theta, double g1, double g2) {
  const double c = std::cos(theta), s = std::sin(theta);
  return 1 / (c * c / g1 + s * s / g2);
}

inline CrackMeasure measure_crack(const Scene& scene, const SolverState& state,
                                  const NotchedBeam& p, double band) {
  const Material& m = scene.materials[0];
  const double g1 = m.fracture_energy, g2 = m.shear_fracture_energy;
  constexpr std::size_t points = SolverState::kBondStatePoints;
  static_assert(points == 2, "a point per half of the edge");
  CrackMeasure c;
  c.ligament = p.depth - p.notch_depth;
  std::vector<std::pair<double, double>> spans;
  double mode2 = 0, broken_energy = 0, weighted_angle = 0;
  for (std::size_t k = 0; k < scene.bonds.size(); ++k) {
    const BondSpec& bond = scene.bonds[k];
    const double e = state.bond_dissipated[k];
    c.total_energy += e;
    const Vec2d edge = bond.q - bond.p, mid = (bond.p + bond.q) * 0.5;
    // The bond's normal is perp(edge); its angle to x is the edge's angle to y.
    const double theta = std::atan(std::abs(edge.x) / std::max(std::abs(edge.y), 1e-300));
    int on_crack = 0, elsewhere = 0;
    for (std::size_t i = 0; i < points; ++i) {
      if (state.bond_damage[k * points + i] < 1) continue;
      // Point i carries the half of the edge on its side of the midpoint (points ascend
      // from p to q).
      const Vec2d from = i == 0 ? bond.p : mid, to = i == 0 ? mid : bond.q;
      if (std::abs(0.5 * (from.x + to.x)) > band) {
        ++elsewhere;
        continue;
      }
      ++on_crack;
      const double half = 0.5 * norm(edge);
      c.path_length += half;
      c.predicted_energy += inclined_bond_energy(theta, g1, g2) * half;
      weighted_angle += theta * 180 / M_PI * half;
      const double lo = std::max(std::min(from.y, to.y), p.notch_depth);
      const double hi = std::min(std::max(from.y, to.y), p.depth);
      if (hi > lo) spans.emplace_back(lo, hi);
    }
    if (on_crack > 0) {
      ++c.crack_bonds;
      c.crack_energy += e;
    } else if (elsewhere > 0) {
      ++c.other_bonds;
      c.other_energy += e;
    } else if (e > 0) {
      ++c.damaged_bonds;
      c.damaged_energy += e;
    }
    if (on_crack == 2) {
      ++c.broken_bonds;
      // E = (G_n + G_s) L with G_n / G_I + G_s / G_II = 1: the part in mode II follows.
      const double g = e / norm(edge);
      mode2 += std::clamp((g - g1) / (1 - g1 / g2), 0.0, g) * norm(edge);
      broken_energy += e;
    }
  }
  std::sort(spans.begin(), spans.end());
  double reach = -1e300;
  for (const auto& [lo, hi] : spans) {
    const double from = std::max(lo, reach);
    if (hi > from) c.projected += hi - from;
    reach = std::max(reach, hi);
  }
  c.mode2_share = broken_energy > 0 ? mode2 / broken_energy : 0;
  c.mean_abs_angle = c.path_length > 0 ? weighted_angle / c.path_length : 0;
  return c;
}

}  // namespace tridem::test
