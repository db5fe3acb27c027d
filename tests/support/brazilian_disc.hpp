#pragma once
// The Brazilian disc test (issue 14; docs/fracture.md): a bonded disc of granite between
// a fixed bottom platen and a top one prescribed downwards at a constant speed; the peak
// platen force F gives the tensile strength sigma_t = 2F/(pi D) per unit thickness.
// Shared by the validation test and the docs' mesh study.
#include "support/brazilian_trace.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tridem::test {

struct BrazilianResult {
  double peak_force = 0;        ///< N/m, on the top platen
  double sigma_t = 0;           ///< 2F/(pi D), Pa
  double tensile_strength = 0;  ///< the material's f_t, Pa
  std::size_t triangles = 0, bonds = 0, broken = 0;
  std::int64_t steps = 0;
  double dt = 0;
};

constexpr double kBrazilianRadius = 0.025;
constexpr double kBrazilianStrength = 8e6;

/// The flats of the test's disc, degrees (ISRM's flattened disc): the platens press on two
/// flats, not on two nodes (docs/fracture.md, "Why the first disc was low").
constexpr double kBrazilianFlatAngle = 20;
/// The test's fracture energies, J/m^2: brittle enough that the disc's diameter is 16
/// characteristic lengths E G_I / f_t^2 (the granite's 30 J/m^2 make it 2.6, and the
/// Brazilian test then reads above f_t: docs/fracture.md).
constexpr double kBrazilianMode1Energy = 5, kBrazilianMode2Energy = 25;

/// The scene: the disc of `size` meshed by Gmsh (throws SceneError without Gmsh), flattened
/// at its poles by flats of `flat_angle` degrees (0: a full disc, touched at its polar
/// nodes), then the two platens, flat-topped triangles touching the flats (or the poles).
inline Scene brazilian_scene(double size, double speed, double flat_angle = kBrazilianFlatAngle,
                             double local_damping = 0.2,
                             double mode1_energy = kBrazilianMode1Energy,
                             double mode2_energy = kBrazilianMode2Energy) {
  const double r = kBrazilianRadius;
  const double y = r * std::cos(0.5 * flat_angle * M_PI / 180.0);
  const std::string toml = fmt::format(
      "[simulation]\nsteps = 1\nsafety = 0.6\nlocal_damping = {damping}\nbackend = \"cpu\"\n"
      "[[material]]\nname = \"granite\"\ndensity = 2650\npenalty = 5e10\nfriction = 0.6\n"
      "young_modulus = 40e9\ntensile_strength = {ft}\nshear_strength = 25e6\n"
      "friction_angle = 35\nfracture_energy = {g1}\nshear_fracture_energy = {g2}\n"
      "[[mesh]]\nkind = \"disc\"\ncenter = [0, 0]\nradius = {r}\nsize = {size}\n"
      "flat_angle = {flat}\nmaterial = \"granite\"\nbonded = true\n"
      "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{r}, {my}], [0, {m2}], [{mr}, {my}]]\n"
      "fixed = true\n"
      "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{mr}, {y}], [0, {r2}], [{r}, {y}]]\n"
      "motion = \"prescribed\"\nvelocity = [0, {v}]\n",
      fmt::arg("damping", local_damping), fmt::arg("g1", mode1_energy),
      fmt::arg("g2", mode2_energy), fmt::arg("ft", kBrazilianStrength), fmt::arg("size", size),
      fmt::arg("flat", flat_angle), fmt::arg("r", r), fmt::arg("mr", -r), fmt::arg("y", y),
      fmt::arg("my", -y), fmt::arg("m2", -y - r), fmt::arg("r2", y + r), fmt::arg("v", -speed));
  return parse_scene(toml, "brazilian_disc.toml");
}

/// Runs the test until the platen force has fallen below half its peak (or `max_steps`),
/// reading the force every `every` steps.
inline BrazilianResult run_brazilian(const Scene& scene, std::int64_t max_steps,
                                     std::int64_t every = 20, std::int64_t trace = 0) {
  SolverConfig config;
  auto solver = make_solver(scene, config);
  BrazilianResult r;
  r.tensile_strength = kBrazilianStrength;
  r.dt = solver->dt();
  Snapshot snap, start;
  solver->snapshot(start, false);
  // The platens are the two [[triangle]]s, read first: ids 0 and 1.
  const std::size_t top = 1;
  while (solver->step() < max_steps) {
    solver->advance(every);
    solver->snapshot(snap, false);
    const double f = std::abs(snap.fy[top]);
    r.peak_force = std::max(r.peak_force, f);
    if (trace > 0 && solver->step() % trace == 0)
      print_trace(snap, start, kBrazilianRadius, f,
                  std::abs(scene.triangles[top].velocity.y) * snap.time);
    if (r.peak_force > 0 && f < 0.5 * r.peak_force) break;
  }
  r.steps = solver->step();
  r.sigma_t = 2 * r.peak_force / (M_PI * 2 * kBrazilianRadius);
  SolverState state;
  solver->save_state(state);
  r.triangles = scene.triangles.size() - 2;
  r.bonds = state.bonds();
  for (std::size_t k = 0; k < state.bonds(); ++k)
    r.broken += state.bond_damage[2 * k] == 1 && state.bond_damage[2 * k + 1] == 1;
  return r;
}

}  // namespace tridem::test
