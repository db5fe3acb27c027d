// What numbering the particles by place again mid-run costs (core/place_numbered_solver):
// dense_pile(n) with its grains numbered at random, stepped in that order by a solver that
// looks at its order after LOOK steps; the step that ends with the look and renumbers is
// timed against the steps before it, and the same look on dense_pile(n) by rows (which
// does not renumber) gives the look's own cost. Prints one line per case.
//   tridem_renumber_cost [n=1e6] [backend=openmp] [precision=float] [look=20]
#include "core/numbering_note.hpp"
#include "core/particle_model.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/solver_factory.hpp"
#include "core/time_step.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/standard_scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <random>
#include <string>

namespace {

double seconds(const std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Steps `scene` in its own order for look - 1 steps, then one step that ends with a look:
/// the mean of the former, the latter, and whether it renumbered.
void measure(const char* name, const tridem::Scene& scene, std::int64_t look) {
  using namespace tridem;
  const ParticleModel model = build_particle_model(scene);
  auto solver =
      make_renumbering_solver(scene, model, scene_order(model),
                              scene_order_maker(estimate_time_step(scene, model), {}), look);
  solver->advance(1);  // first-step set-up apart
  auto t0 = std::chrono::steady_clock::now();
  solver->advance(look - 2);
  const double step = seconds(t0) / static_cast<double>(look - 2);
  t0 = std::chrono::steady_clock::now();
  solver->advance(1);
  const double last = seconds(t0);
  const bool renumbered = solver->statistics().find("again") != std::string::npos;
  std::printf("%-14s n=%zu %s: step %.4f s, step with the look %.4f s (%+.4f s), %s\n", name,
              model.size(), solver->description().c_str(), step, last, last - step,
              renumbered ? "renumbered" : "kept its order");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto n = static_cast<std::size_t>(argc > 1 ? std::stod(argv[1]) : 1e6);
    const std::string backend = argc > 2 ? argv[2] : "openmp";
    const std::string precision = argc > 3 ? argv[3] : "float";
    const std::int64_t look = argc > 4 ? std::stoll(argv[4]) : 20;
    auto set = [&](tridem::Scene s) {
      s.simulation.backend = tridem::value_in(tridem::kBackendNames, backend).value();
      s.simulation.precision = tridem::value_in(tridem::kPrecisionNames, precision).value();
      return s;
    };
    tridem::Scene shuffled = set(tridem::dense_pile(n));
    std::mt19937_64 random(12345);
    std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end() - 3, random);
    measure("shuffled_pile", shuffled, look);
    measure("dense_pile", set(tridem::dense_pile(n)), look);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tridem_renumber_cost: %s\n", e.what());
    return 1;
  }
}
