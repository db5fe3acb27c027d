// Wall time of a solver's steps on a scene file or a standard pile, every step on the
// backend asked for (ThreadUse::Always: no switching to one thread), for the OpenMP
// load study (bench/omp_load/run_omp_load.sh; issue 12). One line of output:
//   scene=... backend=... threads=... steps=... seconds=... s_per_step=... tri_steps_per_s=...
// Usage: tridem_step_timer SCENE BACKEND THREADS STEPS [WARMUP]
//   SCENE    a scene file (.toml), or dense_pile:N
//   BACKEND  cpu or openmp
//   THREADS  OpenMP threads (0 = the runtime's default)
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s SCENE BACKEND THREADS STEPS [WARMUP]\n", argv[0]);
    return 2;
  }
  try {
    const std::string source = argv[1];
    const std::string pile = "dense_pile:";
    tridem::Scene scene = source.rfind(pile, 0) == 0
                              ? tridem::dense_pile(std::stoul(source.substr(pile.size())))
                              : tridem::read_scene(source);
    const auto backend = tridem::value_in(tridem::kBackendNames, argv[2]);
    if (!backend) throw std::runtime_error(std::string("unknown backend ") + argv[2]);
    scene.simulation.backend = *backend;
    tridem::SolverConfig config;
    config.threads = std::stoi(argv[3]);
    config.thread_use = tridem::ThreadUse::Always;
    const std::int64_t steps = std::stoll(argv[4]);
    const std::int64_t warmup = argc > 5 ? std::stoll(argv[5]) : 2;
    auto solver = tridem::make_solver(scene, config);
    solver->set_stage_timing(false);
    solver->advance(warmup);
    const auto start = std::chrono::steady_clock::now();
    solver->advance(steps);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("scene=%s backend=%s threads=%s steps=%lld seconds=%.4f s_per_step=%.3e "
                "tri_steps_per_s=%.4e desc=\"%s\"\n",
                source.c_str(), argv[2], argv[3], static_cast<long long>(steps), seconds,
                seconds / static_cast<double>(steps),
                static_cast<double>(solver->size()) * static_cast<double>(steps) / seconds,
                solver->description().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tridem_step_timer: %s\n", e.what());
    return 1;
  }
  return 0;
}
