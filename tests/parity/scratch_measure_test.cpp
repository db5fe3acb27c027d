// SCRATCH: measurements for the unstable parity tests; not to be committed.
#include "support/backend_test.hpp"
#include "support/bonded_disc.hpp"
#include "support/program_scenes.hpp"
#include "support/rounding_twin.hpp"
#include "tridem/solver_state.hpp"

#include <gtest/gtest.h>
#include <cstdio>
#include <cstdlib>

namespace tridem {
namespace {

Scene shifted(Scene s, double dx, double dy) {
  for (auto& t : s.triangles)
    for (auto& v : t.vertices) v = v + Vec2d{dx, dy};
  for (auto& b : s.bonds) {
    b.p = b.p + Vec2d{dx, dy};
    b.q = b.q + Vec2d{dx, dy};
  }
  return s;
}

test::Difference diff_shifted(const Snapshot& a, Snapshot b, double dx, double dy) {
  for (std::size_t i = 0; i < b.size(); ++i) { b.x[i] -= dx; b.y[i] -= dy; }
  return test::max_difference(a, b);
}

void servo_measure(const Scene& s, const char* name, std::int64_t steps) {
  const double sx = 0.0123456789, sy = 0.0;
  auto ref = make_solver(s, {});
  auto sh = make_solver(shifted(s, sx, sy), {});
  auto sd = test::solver_for(s, test::SolverChoice(Backend::Cpu, Method::SingleDomain));
  test::RoundingTwin tv(make_solver(s, {}), 0x1p-53);
  test::RoundingTwin tp(make_solver(s, {}), 0x1p-53, test::RoundingTwin::Kicks::VelocitiesAndPositions);
  std::printf("%s: dt %.3g\n", name, ref->dt());
  Snapshot a, b;
  test::Difference dsh_max;
  for (std::int64_t k = 100; k <= steps; k += 100) {
    ref->advance(100); sh->advance(100); tv.advance(100); tp.advance(100); sd->advance(100);
    ref->snapshot(a, true); sh->snapshot(b, true);
    const test::Difference d = diff_shifted(a, b, sx, sy);
    Snapshot c; sd->snapshot(c, true);
    const test::Difference dsd = test::max_difference(a, c);
    std::printf("  single-domain dx %.3g dv %.3g\n", dsd.position, dsd.velocity);
    dsh_max.position = std::max(dsh_max.position, d.position);
    dsh_max.velocity = std::max(dsh_max.velocity, d.velocity);
    const test::Difference v = tv.spread_from(a), p = tp.spread_from(a);
    std::printf("  %s step %lld: shifted dx %.3g dv %.3g | twinV dx %.3g dv %.3g | twinP dx %.3g dv %.3g | contacts %zu\n",
                name, (long long)k, dsh_max.position, dsh_max.velocity, v.position, v.velocity, p.position, p.velocity,
                a.contacts.size());
  }
}

TEST(Scratch, Servo) {
  const char* rows_env = std::getenv("ROWS");
  const int rows = rows_env ? std::atoi(rows_env) : 5;
  const char* b = std::getenv("BODIES");
  Scene s = b ? test::servo_box_of_bodies(true, rows) : test::servo_box(true, rows);
  servo_measure(s, b ? "bodies" : "triangles", 3000);
}

void bond_line(const char* name, Solver& solver, const Snapshot& ref, double sx) {
  Snapshot b;
  solver.snapshot(b, true);
  const test::Difference d = diff_shifted(ref, b, sx, 0);
  SolverState st;
  solver.save_state(st);
  const auto c = test::count_bonds(st);
  const EnergyBudget e = solver.energy();
  std::printf("    %-8s dx %.3g dv %.3g elastic %.5g fracture %.5g wall %.5g damaged %zu broken %zu platen f %.5g\n", name,
              d.position, d.velocity, e.elastic, e.dissipated_fracture, e.wall_work, c.damaged, c.broken,
              b.fy[1]);
}

TEST(Scratch, BondFloat) {
  Scene s = test::loaded_bonded_disc();
  const char* p = std::getenv("DOUBLE");
  const Precision prec = p ? Precision::Double : Precision::Float;
  const test::SolverChoice cpu(Backend::Cpu, Method::Grid, prec);
  const double sx = 0.0123456789;
  auto ref = test::solver_for(s, cpu);
  auto sh = test::solver_for(shifted(s, sx, 0), cpu);
  auto dbl = test::solver_for(s, test::SolverChoice(Backend::Cpu));
  auto sd = test::solver_for(s, test::SolverChoice(Backend::Cpu, Method::Decomposition, prec));
  const double eps = p ? 0x1p-53 : 0x1p-24;
  std::vector<std::unique_ptr<test::RoundingTwin>> twins;
  for (std::uint64_t seed : {12345ULL, 1ULL, 2ULL, 3ULL})
    twins.push_back(std::make_unique<test::RoundingTwin>(test::solver_for(s, cpu), eps, test::RoundingTwin::Kicks::Velocities, seed));
  twins.push_back(std::make_unique<test::RoundingTwin>(test::solver_for(s, cpu), eps, test::RoundingTwin::Kicks::VelocitiesAndPositions));
  Snapshot a;
  for (std::int64_t k = 50; k <= 600; k += 50) {
    ref->advance(50); sh->advance(50); dbl->advance(50); sd->advance(50);
    for (auto& t : twins) t->advance(50);
    ref->snapshot(a, true);
    std::printf("step %lld\n", (long long)k);
    bond_line("ref", *ref, a, 0);
    bond_line("shifted", *sh, a, sx);
    bond_line("double", *dbl, a, 0);
    bond_line("decomp", *sd, a, 0);
    for (std::size_t i = 0; i < twins.size(); ++i) bond_line(i + 1 < twins.size() ? "twinV" : "twinP", twins[i]->solver(), a, 0);
  }
}

}  // namespace
}  // namespace tridem
