#pragma once
// A whole run: solver, time loop, output cadence, progress and summary. The app is a thin
// shell over this, and tests drive it too.
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

namespace tridem {

struct RunOptions {
  std::optional<std::string> out_dir;     ///< overrides [output] dir
  std::optional<Backend> backend;         ///< overrides [simulation] backend
  std::optional<std::int64_t> steps;      ///< overrides [simulation] steps
  std::optional<Method> method;           ///< overrides [simulation] method
  std::optional<ContactTest> contact_test; ///< overrides [simulation] contact_test
  std::optional<bool> bbox_prefilter;     ///< overrides [simulation] bbox_prefilter
  bool force = false;                     ///< accept dt above dt_crit
  int threads = 0;                        ///< OpenMP threads, 0 = default
  bool progress = true;                   ///< bar on stderr when it is a terminal
  std::FILE* log = stdout;                ///< where the start and summary lines go
};

struct RunSummary {
  std::int64_t steps = 0;
  std::size_t triangles = 0;
  double seconds = 0;                     ///< time-loop wall time, outputs included
  double steps_per_second = 0;
  double triangle_steps_per_second = 0;
  std::string solver;
};

/// Runs the scene to the end, writing its outputs. Throws tridem::Error on failure.
RunSummary run_scene(const Scene& scene, const RunOptions& options);

/// What `tridem info` prints about a scene.
struct SceneInfo {
  std::size_t triangles = 0, free = 0, fixed = 0, prescribed = 0;
  Vec2d box_lo{}, box_hi{};
  double longest_edge = 0;
  double dt_critical = 0, dt_chosen = 0;
  bool dt_automatic = true;
  std::size_t memory_bytes = 0;           ///< estimated memory of a run (solver and host)
  std::size_t gpu_memory_bytes = 0;       ///< GPU memory the cuda backend reserves at start
                                          ///< (0 in a build without CUDA)
  std::string gpu;                        ///< the GPU found, empty when none is usable
};

SceneInfo describe_scene(const Scene& scene);

}  // namespace tridem
