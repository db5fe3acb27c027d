// Writes tests/data/regression/pair_forces.csv: random overlapping pairs of moving
// triangles with a stored slip, and the pair force tridem computes for them. Run it only
// when the contact model changes on purpose (and say so in the commit):
//   build/tests/make_reference_forces > tests/data/regression/pair_forces.csv
#include "physics/contact_force.hpp"
#include "physics/restitution.hpp"

#include <cstdio>
#include <random>

int main() {
  using namespace tridem;
  using namespace tridem::physics;
  std::mt19937_64 rng(2026);
  auto u = [&rng]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
  std::printf("# a: x1 y1 x2 y2 x3 y3 vx vy w mass | b: same | law: p pt mu zeta1 zeta1.5 zeta2 | "
              "dt | slip x y | out: fx fy ta tb px py slip x y elastic damped rubbed\n");
  int written = 0;
  while (written < 40) {
    Body<double> body[2];
    for (int k = 0; k < 2; ++k) {
      const Vec2d shift{k * 0.5 * u(), k * 0.5 * u()};
      for (auto& v : body[k].tri.v) v = Vec2d{u(), u()} + shift;
      if (signed_area(body[k].tri) < 0) std::swap(body[k].tri.v[1], body[k].tri.v[2]);
      body[k].c = centroid(body[k].tri);
      body[k].area = signed_area(body[k].tri);
      body[k].v = {u(), u()};
      body[k].w = 5 * u();
      body[k].mass = written % 5 == 4 && k == 1 ? 0.0 : 1 + u() * 0.5;  // some walls
    }
    if (body[0].area < 0.05 || body[1].area < 0.05) continue;
    if (!triangles_overlap(body[0].tri, body[1].tri)) continue;
    const double mu = 0.5 + 0.4 * u();
    const ContactLaw<double> law = contact_law(1e6, 1e5, mu, 0.5 + 0.3 * u());
    const double dt = 1e-4;
    PairSlip<double> slip;
    for (double& s : slip.s) s = 1e-6 * u();
    for (const auto& b : body) {
      for (const auto& v : b.tri.v) std::printf("%.17g %.17g ", v.x, v.y);
      std::printf("%.17g %.17g %.17g %.17g ", b.v.x, b.v.y, b.w, b.mass);
    }
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g ", law.penalty,
                law.tangential_penalty, law.friction, law.damping[0], law.damping[1],
                law.damping[2], dt);
    for (double s : slip.s) std::printf("%.17g ", s);
    const PairForce<double> f = pair_force(body[0], body[1], law, dt, slip);
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g", f.force_a.x, f.force_a.y, f.torque_a,
                f.torque_b, f.point.x, f.point.y);
    for (double s : slip.s) std::printf(" %.17g", s);
    std::printf(" %.17g %.17g %.17g\n", f.elastic_energy, f.damping_dissipation,
                f.friction_dissipation);
    ++written;
  }
}
