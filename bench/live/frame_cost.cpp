// What one live frame costs the stepping thread, before and after issue 18's second part,
// on a scene's solver (bench/live/run_live_bench.sh runs it for each size): the old path
// (Solver::snapshot, energy() and the float frame filled, all on the stepping thread) and
// the new one (StateCopy::start on the stepping thread; finish, the frame's floats and
// the encoding on the server's thread). Minimum and median of REPEATS frames, taken
// between steps; the minimum is what the work takes on a quiet core.
//   tridem_live_frame_cost SCENE [REPEATS]
#include "live/frame_encoder.hpp"
#include "tridem/output.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Times {
  std::vector<double> ms;
  void add(Clock::time_point t0) {
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  double min() const { return *std::min_element(ms.begin(), ms.end()); }
  double median() {
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE [REPEATS]\n", argv[0]);
    return 2;
  }
  try {
    const tridem::Scene scene = tridem::read_scene(argv[1]);
    const int repeats = argc > 2 ? std::stoi(argv[2]) : 20;
    auto solver = tridem::make_solver(scene, {});
    solver->advance(2);
    const tridem::Vec2d g = scene.simulation.gravity;
    tridem::Snapshot snap, frame_state;
    tridem::live::FrameData frame;
    solver->snapshot(frame_state, false);  // the live view's first look
    const auto copy = solver->make_state_copy();
    Times old_path, start, server;
    for (int k = 0; k < repeats; ++k) {
      auto t0 = Clock::now();
      solver->snapshot(snap, false);
      tridem::live::fill_frame(snap, tridem::compute_energy(snap, g, solver->energy()), frame);
      old_path.add(t0);
      t0 = Clock::now();
      copy->start();
      start.add(t0);
      solver->advance(1);  // the steps go on while the server converts
      t0 = Clock::now();
      const tridem::EnergyBudget budget = copy->finish(frame_state);
      tridem::live::fill_frame(frame_state, tridem::compute_energy(frame_state, g, budget), frame);
      const std::string bytes = tridem::live::encode_frame(frame);
      server.add(t0);
      if (bytes.empty()) return 1;
    }
    std::printf("{\"triangles\": %zu, \"solver\": \"%s\", \"frames\": %d, "
                "\"old_stepping_ms_min\": %.3f, \"old_stepping_ms_median\": %.3f, "
                "\"new_stepping_ms_min\": %.3f, \"new_stepping_ms_median\": %.3f, "
                "\"server_ms_min\": %.3f, \"server_ms_median\": %.3f}\n",
                solver->size(), solver->description().c_str(), repeats, old_path.min(),
                old_path.median(), start.min(), start.median(), server.min(), server.median());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frame cost: %s\n", e.what());
    return 1;
  }
  return 0;
}
