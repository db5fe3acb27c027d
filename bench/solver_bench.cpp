// Solver benchmark: triangle-steps per second of the serial reference solver (backend
// cpu) and of its OpenMP twin (backend openmp) on the standard dense settling pile,
// dense_pile(n), for n = 10^3 .. 10^8 (10^8 only with --max_n=1e8), and the GPU solver
// (backend cuda). See bench/README.md for how to run and read it.
//
// Each case is one Google Benchmark run per repetition: a fresh pile is built and warmed
// up outside timing, then every timed iteration advances the solver by k steps; the whole
// timed window lies in the first 52 steps, where the pile is dense at every size (see
// kWarmupSteps). Counters:
//   tri_steps_per_s  triangles × steps per second of wall time (the figure of merit)
//   s_per_step       wall seconds per step
//   threads          OpenMP threads the solver runs with (1 for the serial solver)
//   triangles        solver->size(): grains plus the 3 fixed wall triangles
//   steps_per_iter   k
//   first_step       the first timed step (after the warm-up and, for settled_pile, the
//                    settling steps)
//   contacts_per_tri touching pairs per triangle at the end of the window (density check)
//   rms_speed        root mean square speed of the free grains then, m/s (how settled)
//   stage_<name>     seconds per step of each stage in the timed window (Solver::
//                    stage_times(): steady_clock on the CPU, CUDA events on the GPU); a
//                    stage the backend fuses into another one's kernel has no counter
//
// Extra flags (before or among the --benchmark_* ones):
//   --max_n=N         skip sizes above N (e.g. --max_n=1e5 to fit a time budget)
//   --min_n=N         skip sizes below N
//   --backends=LIST   cpu,openmp,cuda,cuda-float,cpu-float,openmp-float (default
//                     cpu,openmp); NAME-float is the backend in precision = "float" (the
//                     mixed mode: double state, float pairs; docs/model.md, "Precision"),
//                     the others double
//   --stage_timing=0  run without per-stage times (what timing costs: compare s_per_step)
//   --frames=1        also time one output frame (snapshot) per variant, size and scene
//   --contact_rows_per_copy=R  rows of a frame's contact network the cuda backend
//                     compacts and downloads at a time (default 2^22; a number above the
//                     contacts takes them in one piece, as before windows)
//   --large_reps=R    repetitions for n >= 10^6 (default: --benchmark_repetitions)
//   --iter_scale=X    multiply every fixed iteration count by X (at least 1 iteration);
//                     more iterations also move the window later into the decompression
//   --method=NAME     grid (default), all-pairs, single-domain, decomposition: how pairs
//                     are found (single-domain is O(n²) per step: keep --max_n small)
//   --contact_test=T  exact (default) or direct-area, for single-domain and decomposition
//   --bbox_prefilter=0  the paper's pre-filter off (single-domain and decomposition)
//   --layout=1d|2d, --rows=N, --columns=N, --capacity=N
//                     [simulation.decomposition] for --method=decomposition (default 1d,
//                     capacity 256; rows and columns 2d only, chosen when not given)
//   --scenes=LIST     dense_pile (default), body_pile, bonded_pile, or several: body_pile(n)
//                     is dense_pile(n) with its grains grouped into rigid bodies of 10
//                     triangles (issue 13: 10^6 triangles in 10^5 bodies against
//                     dense_pile(10^6)); bonded_pile(n) is dense_pile(n) with every grain
//                     bonded to its lattice neighbours (issue 14: about 1.5 cohesive bonds
//                     per triangle; counter `bonds`); their cases are <scene>/<backend>/n:<n>
//                     settled_pile(n) is dense_pile(n) as deep as at 10^4 (0.66 m; wider
//                     at larger n) after --settle_steps steps under gravity (issue 12: a
//                     settled pile beside the dense one), stepped once
//                     per size and precision by the fastest backend there (cuda, else
//                     openmp), kept as a SolverState (what a checkpoint holds) and loaded
//                     into each repetition's solver; counter `settle_steps`;
//                     shuffled_pile(n) is dense_pile(n) with its grains numbered in a
//                     random order (fixed seed): what the particles' order costs;
//                     curve_pile(n) numbers them along a Hilbert curve (numbering = "space");
//                     shuffled_body_pile(n) is body_pile(n) with its bodies in a random
//                     order (members together); sheared_pile(n) numbers dense_pile(n)'s
//                     grains along the curve through where they were before a simple
//                     shear of strain --order_strain (x - strain·y): the order a flow
//                     numbered by place leaves after that strain (counter `apart`, the
//                     numbering's mean distance between consecutive grains in grain sizes,
//                     and `blocks`, its neighbour_block_spread: core/neighbour_blocks.hpp)
//   --order_strain=X  sheared_pile's strain (default 10)
//   --particle_order=auto|scene|place  SolverConfig::particle_order (default auto, as
//                     tridem run: shuffled_pile from 10^5 is then numbered by place inside
//                     the solver; scene measures the scene's random order)
//   --settle_steps=N  steps that settle settled_pile (default 50000)
//   --run_ahead=0     the CUDA solver without run-ahead (each step waits for the status of
//                     the one before it; the default launches each step before that status
//                     is read: docs/performance.md, "Run-ahead"; the same results)
//   --skin=X          every case's [simulation] skin (default the scenes' 0.05): the CUDA
//                     list's and the CPU solvers' kept list's; 0 builds the CPU list every
//                     step from the boxes themselves (same results: what keeping it gives)
#include "backends/cuda/cuda_backend.hpp"
#include "bench_flags.hpp"
#include "core/neighbour_blocks.hpp"
#include "core/numbering_note.hpp"
#include "core/particle_model.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/space_filling_order.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using tridem::Backend;

/// The measured window of the run. dense_pile(n) starts with every lattice neighbour
/// overlapping; from the free top surface the pile then decompresses, at the speed of sound,
/// so that a small pile loses its dense contact network within a few hundred steps (10^3
/// grains: 5.7 contacts per triangle at step 10, 4.1 at step 100, 2.3 at step 200). To
/// measure every size in the same dense state, each repetition starts from a fresh pile,
/// runs kWarmupSteps untimed steps (first touch of every array, pair lists grown to their
/// working size), then times `iterations × steps_per_iteration` steps, at most 50 in all.
constexpr std::int64_t kWarmupSteps = 2;

struct Work {
  std::int64_t steps_per_iteration;  ///< k: steps done by one solver->advance(k)
  std::int64_t iterations;           ///< timed iterations per repetition
};

/// About 5·10^4 .. 10^7 triangle-steps per repetition: ≳0.1 s of serial work at every
/// size on a typical core. At least 10 steps an advance, as the GPU's: the solvers compute
/// the pairs' stored energy on an advance's last step only (as a run does, on the steps it
/// writes), and that step costs a CPU solver some 13 % more; with one or two steps an
/// advance (before 2026-12-04) the CPU cases paid it on every or every other step.
Work work(std::size_t n) {
  if (n >= 100000) return {10, 1};
  if (n >= 10000) return {10, 2};
  return {50, 1};
}

/// The GPU does a step in well under a millisecond: it times more steps per iteration, still
/// inside the dense window of each size (the first 52 steps below 10^6; the first 32 at
/// 10^6 and above, where the pile stays dense for thousands of steps).
Work gpu_work(std::size_t n) {
  if (n >= 1000000) return {10, 3};
  return {50, 1};
}

/// A solver to measure: a backend in one precision.
struct Variant {
  Backend backend;
  tridem::Precision precision;

  /// "cpu", "openmp", "cuda", "cuda-float": the backend's spelling, and the precision's
  /// when it is not double.
  std::string name() const {
    std::string out(tridem::backend_name(backend));
    if (precision != tridem::Precision::Double) {
      out += '-';
      out += tridem::precision_name(precision);
    }
    return out;
  }
};

const Variant kVariants[] = {
    {Backend::Cpu, tridem::Precision::Double},  {Backend::OpenMP, tridem::Precision::Double},
    {Backend::Cuda, tridem::Precision::Double}, {Backend::Cuda, tridem::Precision::Float},
    {Backend::Cpu, tridem::Precision::Float},   {Backend::OpenMP, tridem::Precision::Float},
};

/// --stage_timing: per-stage times on (the default) or off.
bool g_stage_timing = true;

/// How pairs are found in every case (--method, --contact_test, --bbox_prefilter).
tridem::SimulationSettings g_method;

/// --skin: the scenes' skin, when given.
std::optional<double> g_skin;

/// --run_ahead=0: the CUDA solver waits for each step's status before it launches the next.
bool g_run_ahead = true;

/// --contact_rows_per_copy: SolverConfig::gpu_contact_rows_per_copy (0 = its default).
std::size_t g_contact_rows_per_copy = 0;

/// --particle_order: SolverConfig::particle_order.
tridem::ParticleOrder g_particle_order = tridem::ParticleOrder::Auto;

/// Which standard pile a case measures.
enum class Pile { Dense, Bodies, Bonded, Settled, Shuffled, Curve, ShuffledBodies, Sheared };
constexpr Pile kPiles[] = {Pile::Dense,    Pile::Bodies, Pile::Bonded,         Pile::Settled,
                           Pile::Shuffled, Pile::Curve,  Pile::ShuffledBodies, Pile::Sheared};
const char* pile_name(Pile p) {
  switch (p) {
    case Pile::Dense: return "dense_pile";
    case Pile::Bodies: return "body_pile";
    case Pile::Bonded: return "bonded_pile";
    case Pile::Settled: return "settled_pile";
    case Pile::Shuffled: return "shuffled_pile";
    case Pile::Curve: return "curve_pile";
    case Pile::ShuffledBodies: return "shuffled_body_pile";
    case Pile::Sheared: return "sheared_pile";
  }
  return "";
}

/// --order_strain: sheared_pile's strain.
double g_order_strain = 10;

/// --settle_steps: how long settled_pile settles.
std::int64_t g_settle_steps = 50000;
/// While settled_pile settles, its grains are stopped every kRelaxEvery steps.
constexpr std::int64_t kRelaxEvery = 1000;

tridem::Scene make_pile(Pile kind, std::size_t n) {
  switch (kind) {
    case Pile::Dense: return tridem::dense_pile(n);
    // As deep as dense_pile(10^4) at every size (0.66 m: wider, not deeper), so that the
    // same --settle_steps settle it.
    case Pile::Settled:
      return tridem::dense_pile(n, 0.01, std::max(1.0, static_cast<double>(n) / 1e4));
    case Pile::Bodies: return tridem::body_pile(n);
    case Pile::Bonded: return tridem::bonded_pile(n);
    case Pile::Shuffled: {
      // The same grains in an order unrelated to where they lie (a fixed seed), as a scene
      // poured or imported rather than generated row by row numbers them: what the
      // particles' order costs a solver's memory traffic. The walls stay last.
      tridem::Scene s = tridem::dense_pile(n);
      s.source = "shuffled_pile";
      std::mt19937_64 random(12345);
      std::shuffle(s.triangles.begin(), s.triangles.end() - 3, random);
      return s;
    }
    case Pile::Curve: {
      // Numbered along the Hilbert curve through the centroids, as [[generate]]'s
      // numbering = "space" numbers its grains; the walls stay last.
      tridem::Scene s = tridem::dense_pile(n);
      s.source = "curve_pile";
      tridem::number_by_place(s.triangles, s.triangles.size() - 3);
      return s;
    }
    case Pile::Sheared: {
      // Numbered along the curve where the grains were a strain ago (x - strain·y: a simple
      // shear along x), as a run numbered by place finds its grains after that strain; the
      // walls stay last. The same triangles as dense_pile's, in that order.
      tridem::Scene s = tridem::dense_pile(n);
      s.source = "sheared_pile";
      const std::size_t grains = s.triangles.size() - 3;
      std::vector<tridem::Vec2d> before(grains);
      for (std::size_t i = 0; i < grains; ++i) {
        const auto& v = s.triangles[i].vertices;
        const tridem::Vec2d c = (v[0] + v[1] + v[2]) / 3.0;
        before[i] = {c.x - g_order_strain * c.y, c.y};
      }
      const std::vector<std::size_t> order = tridem::space_filling_order(before);
      std::vector<tridem::TriangleSpec> grains_in_order(grains);
      for (std::size_t k = 0; k < grains; ++k) grains_in_order[k] = s.triangles[order[k]];
      std::copy(grains_in_order.begin(), grains_in_order.end(), s.triangles.begin());
      return s;
    }
    case Pile::ShuffledBodies: {
      // body_pile with its bodies (of 10 triangles) in a random order, members together:
      // generated polygons are numbered in their placement order so.
      const tridem::Scene bodies = tridem::body_pile(n);
      std::vector<std::int32_t> order(bodies.bodies.size());
      std::iota(order.begin(), order.end(), 0);
      std::mt19937_64 random(12345);
      std::shuffle(order.begin(), order.end() - 3, random);  // the walls stay last
      tridem::Scene s = tridem::reordered_scene(bodies, tridem::body_order(bodies, order));
      s.source = "shuffled_body_pile";
      return s;
    }
  }
  return {};
}

/// The scene of the last pile and size asked for: built once per size, not once per
/// repetition.
const tridem::Scene& pile(Pile kind, std::size_t n) {
  static std::size_t cached_n = 0;
  static Pile cached_kind = Pile::Dense;
  static tridem::Scene scene;
  if (cached_n != n || cached_kind != kind) {
    scene = make_pile(kind, n);
    cached_kind = kind;
    scene.simulation.method = g_method.method;
    scene.simulation.contact_test = g_method.contact_test;
    scene.simulation.bbox_prefilter = g_method.bbox_prefilter;
    scene.simulation.decomposition = g_method.decomposition;
    if (g_skin) scene.simulation.skin = *g_skin;
    cached_n = n;
  }
  return scene;
}

/// settled_pile's state in `precision`: dense_pile(n) stepped g_settle_steps steps by the
/// fastest backend there, once per size and precision (the last one asked for is kept).
const tridem::SolverState& settled_state(std::size_t n, tridem::Precision precision) {
  static std::size_t cached_n = 0;
  static tridem::Precision cached_precision = tridem::Precision::Double;
  static tridem::SolverState state;
  if (cached_n != n || cached_precision != precision) {
    tridem::Scene scene = pile(Pile::Settled, n);
    scene.simulation.backend = tridem::cuda_available(nullptr) ? Backend::Cuda : Backend::OpenMP;
    scene.simulation.precision = precision;
    const auto settling = tridem::make_solver(scene, tridem::SolverConfig{});
    // Kinetic relaxation: every kRelaxEvery steps every grain is stopped, so that the
    // pre-stressed pile's energy leaves and the pile comes to rest under gravity. Without
    // it the pile of 10^4 still moved at 0.54 m/s (root mean square) after 4x10^4 steps,
    // with local damping 0.8 at 0.35 m/s after 2x10^4 (OpenMP, this 2-core machine); with
    // it, 0.025 m/s after 5x10^4.
    for (std::int64_t done = 0; done < g_settle_steps; done += kRelaxEvery) {
      settling->advance(std::min(kRelaxEvery, g_settle_steps - done));
      settling->save_state(state);
      for (auto* v : {&state.vx, &state.vy, &state.omega}) std::fill(v->begin(), v->end(), 0.0);
      settling->load_state(state);
    }
    // The last stop is not the measured state: the pile steps on a while after it.
    settling->advance(kRelaxEvery);
    settling->save_state(state);
    cached_n = n;
    cached_precision = precision;
  }
  return state;
}

std::unique_ptr<tridem::Solver> make(const Variant& v, Pile kind, std::size_t n) {
  tridem::Scene scene = pile(kind, n);
  scene.simulation.backend = v.backend;
  scene.simulation.precision = v.precision;
  tridem::SolverConfig config;
  config.gpu_run_ahead = g_run_ahead;
  config.gpu_contact_rows_per_copy = g_contact_rows_per_copy;
  config.particle_order = g_particle_order;
  auto solver = tridem::make_solver(scene, config);
  if (kind == Pile::Settled) solver->load_state(settled_state(n, v.precision));
  return solver;
}

/// A solver past its warm-up steps, or none (the case then reports why and is skipped).
std::unique_ptr<tridem::Solver> warmed_up(benchmark::State& state, const Variant& v, std::size_t n,
                                          Pile kind = Pile::Dense) {
  try {
    auto solver = make(v, kind, n);
    solver->advance(kWarmupSteps);
    return solver;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    for (auto _ : state) {
    }
    return nullptr;
  }
}

void pile_case(benchmark::State& state, Variant v, Pile kind, std::size_t n, std::int64_t k) {
  const Backend backend = v.backend;
  const std::unique_ptr<tridem::Solver> solver = warmed_up(state, v, n, kind);
  if (!solver) return;
  solver->set_stage_timing(g_stage_timing);
  const tridem::StageTimes before = solver->stage_times();
  try {
    for (auto _ : state) solver->advance(k);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  // Untimed: how dense the pile still is at the end of the window.
  tridem::Snapshot snap;
  solver->snapshot(snap, true);
  const double tri = static_cast<double>(solver->size());
  using benchmark::Counter;
  state.counters["tri_steps_per_s"] = Counter(tri * static_cast<double>(k),
                                              Counter::kIsIterationInvariantRate);
  // seconds / (k·iterations): wall seconds per step (the console prints it as ms, us)
  state.counters["s_per_step"] = Counter(static_cast<double>(k),
                                         Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["threads"] =
      backend == Backend::Cpu ? 1 : (backend == Backend::OpenMP ? omp_get_max_threads() : 0);
  state.counters["triangles"] = tri;
  state.counters["steps_per_iter"] = static_cast<double>(k);
  const std::int64_t settled = kind == Pile::Settled ? g_settle_steps : 0;
  state.counters["first_step"] = static_cast<double>(settled + kWarmupSteps + 1);
  state.counters["settle_steps"] = static_cast<double>(settled);
  state.counters["contacts_per_tri"] = static_cast<double>(snap.contacts.size()) / tri;
  {
    const tridem::ParticleModel model = tridem::build_particle_model(pile(kind, n));
    state.counters["apart"] = tridem::consecutive_id_distance(model);
    std::vector<std::uint8_t> free(model.size());
    for (std::size_t i = 0; i < free.size(); ++i) free[i] = model.motion[i] == tridem::Motion::Free;
    state.counters["blocks"] =
        tridem::neighbour_block_spread(model.centroid, free, tridem::free_grain_size(model));
  }
  double v2 = 0;
  std::size_t free = 0;
  for (std::size_t i = 0; i < snap.size(); ++i)
    if (snap.motion[i] == tridem::Motion::Free) {
      v2 += snap.vx[i] * snap.vx[i] + snap.vy[i] * snap.vy[i];
      ++free;
    }
  state.counters["rms_speed"] = free > 0 ? std::sqrt(v2 / static_cast<double>(free)) : 0.0;
  state.counters["bodies"] = static_cast<double>(snap.body_count());
  state.counters["bonds"] = static_cast<double>(snap.bond_a.size());
  const tridem::StageTimes after = solver->stage_times();
  const auto steps = static_cast<double>(after.steps - before.steps);
  for (int s = 0; s < tridem::kStageCount && steps > 0; ++s) {
    if (after.fused_into[s] != s) continue;
    std::string name = tridem::stage_name(static_cast<tridem::Stage>(s));
    std::replace(name.begin(), name.end(), ' ', '_');
    state.counters["stage_" + name] = (after.seconds[s] - before.seconds[s]) / steps;
  }
  const std::string stats = solver->statistics();
  state.SetLabel(solver->description() + (stats.empty() ? "" : "; " + stats));
}

/// The cost of one output frame: the state (6 arrays of n in double in every precision)
/// and the forces (3 in the precision) copied from the solver's memory into a host
/// Snapshot, without and with the contact network.
void snapshot_case(benchmark::State& state, Variant v, Pile kind, std::size_t n, bool contacts) {
  const std::unique_ptr<tridem::Solver> solver = warmed_up(state, v, n, kind);
  if (!solver) return;
  tridem::Snapshot snap;
  // A run's frames after its first two: the buffers grown (a solver numbering by place
  // swaps its contacts' buffer with the snapshot's, so that both grow in two frames).
  for (int warm = 0; warm < 2; ++warm) solver->snapshot(snap, contacts);
  for (auto _ : state) solver->snapshot(snap, contacts);
  const double real = v.precision == tridem::Precision::Float ? 4 : 8;
  using benchmark::Counter;
  state.counters["s_per_frame"] = Counter(1, Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["state_bytes"] = (6 * 8 + 3 * real) * static_cast<double>(solver->size());
  state.counters["contacts"] = static_cast<double>(snap.contacts.size());
  state.counters["triangles"] = static_cast<double>(solver->size());
  state.SetLabel(solver->description());
}

}  // namespace

int main(int argc, char** argv) {
  using tridem::bench::parse_number;
  using tridem::bench::take_flag;
  const std::string max_n_flag = take_flag(argc, argv, "max_n");
  const std::string min_n_flag = take_flag(argc, argv, "min_n");
  const std::string backends_flag = take_flag(argc, argv, "backends");
  const std::string large_reps_flag = take_flag(argc, argv, "large_reps");
  const std::string iter_scale_flag = take_flag(argc, argv, "iter_scale");
  const double max_n = max_n_flag.empty() ? 1e6 : parse_number("tridem_bench", "max_n", max_n_flag);
  const double min_n = min_n_flag.empty() ? 1e3 : parse_number("tridem_bench", "min_n", min_n_flag);
  const int large_reps =
      large_reps_flag.empty() ? 0 : static_cast<int>(parse_number("tridem_bench", "large_reps", large_reps_flag));
  const double iter_scale =
      iter_scale_flag.empty() ? 1.0 : parse_number("tridem_bench", "iter_scale", iter_scale_flag);
  std::vector<Variant> variants;
  const std::string list = backends_flag.empty() ? "cpu,openmp" : backends_flag;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    const auto* v = std::find_if(std::begin(kVariants), std::end(kVariants),
                                 [&](const Variant& x) { return name == x.name(); });
    if (v == std::end(kVariants)) {
      std::cerr
          << "tridem_bench: --backends wants a list of cpu, openmp, cuda, cuda-float, cpu-float, "
             "openmp-float; got '"
          << name << "'\n";
      return 2;
    }
    variants.push_back(*v);
    start = comma + 1;
  }
  const bool frames = !take_flag(argc, argv, "frames").empty();
  std::vector<Pile> piles;
  {
    const std::string scenes_flag = take_flag(argc, argv, "scenes");
    const std::string scenes = scenes_flag.empty() ? "dense_pile" : scenes_flag;
    for (std::size_t at = 0; at <= scenes.size();) {
      const std::size_t comma = std::min(scenes.find(',', at), scenes.size());
      const std::string name = scenes.substr(at, comma - at);
      const auto* p = std::find_if(std::begin(kPiles), std::end(kPiles),
                                   [&](Pile x) { return name == pile_name(x); });
      if (p == std::end(kPiles)) {
        std::cerr
            << "tridem_bench: --scenes wants a list of dense_pile, body_pile, bonded_pile, "
               "settled_pile, shuffled_pile, curve_pile, shuffled_body_pile, sheared_pile; got '"
            << name << "'\n";
        return 2;
      }
      piles.push_back(*p);
      at = comma + 1;
    }
  }
  if (const std::string text = take_flag(argc, argv, "order_strain"); !text.empty())
    g_order_strain = parse_number("tridem_bench", "order_strain", text);
  if (const std::string text = take_flag(argc, argv, "settle_steps"); !text.empty())
    g_settle_steps = static_cast<std::int64_t>(parse_number("tridem_bench", "settle_steps", text));
  g_run_ahead = take_flag(argc, argv, "run_ahead") != "0";
  if (const std::string text = take_flag(argc, argv, "contact_rows_per_copy"); !text.empty())
    g_contact_rows_per_copy =
        static_cast<std::size_t>(parse_number("tridem_bench", "contact_rows_per_copy", text));
  if (const std::string text = take_flag(argc, argv, "skin"); !text.empty())
    g_skin = tridem::bench::parse_number_in("tridem_bench", "skin", text, 0, 1,
                                            "a number in [0, 1] (a fraction of the grid cell)");
  const std::string prefilter_flag = take_flag(argc, argv, "bbox_prefilter");
  tridem::DecompositionSettings& d = g_method.decomposition;
  using tridem::bench::take_choice;
  if (!take_choice("tridem_bench", argc, argv, "method", tridem::kMethodNames, g_method.method) ||
      !take_choice("tridem_bench", argc, argv, "contact_test", tridem::kContactTestNames,
                   g_method.contact_test) ||
      !take_choice("tridem_bench", argc, argv, "layout", tridem::kLayoutNames, d.layout) ||
      !take_choice("tridem_bench", argc, argv, "particle_order", tridem::kParticleOrderNames,
                   g_particle_order))
    return 2;
  g_method.bbox_prefilter = prefilter_flag != "0";
  g_stage_timing = take_flag(argc, argv, "stage_timing") != "0";
  for (auto [flag, value] : {std::pair{"rows", &d.rows}, std::pair{"columns", &d.columns},
                             std::pair{"capacity", &d.capacity}})
    if (const std::string text = take_flag(argc, argv, flag); !text.empty())
      *value = static_cast<int>(parse_number("tridem_bench", flag, text));
  std::string method_tag =
      g_method.method == tridem::Method::Grid ? "" : "/" + std::string(tridem::method_name(g_method.method));
  if (g_method.method == tridem::Method::Decomposition)
    method_tag += "-" + std::string(tridem::name_in(tridem::kLayoutNames, d.layout)) + "-" +
                  std::to_string(d.capacity);

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  benchmark::AddCustomContext("cpu_model", tridem::bench::cpu_model());
  benchmark::AddCustomContext("hardware_threads",
                              std::to_string(std::thread::hardware_concurrency()));
  benchmark::AddCustomContext("omp_max_threads", std::to_string(omp_get_max_threads()));
  benchmark::AddCustomContext("compiler", TRIDEM_BENCH_COMPILER);
  benchmark::AddCustomContext("tridem_build_type", TRIDEM_BENCH_BUILD_TYPE);
  benchmark::AddCustomContext("tridem_version", TRIDEM_VERSION);
  benchmark::AddCustomContext("gpu", tridem::cuda_device_description());
  std::string scene_names;
  for (Pile p : piles)
    scene_names += std::string(scene_names.empty() ? "" : ", ") + pile_name(p) + "(n)";
  benchmark::AddCustomContext("scene",
                              scene_names + ", method " +
                                  tridem::method_description(g_method.method, g_method.contact_test,
                                                             g_method.bbox_prefilter));

  for (const std::size_t n :
       {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}, std::size_t{1000000},
        std::size_t{10000000}, std::size_t{100000000}}) {
    if (static_cast<double>(n) > max_n || static_cast<double>(n) < min_n) continue;
    for (const Variant& v : variants) {
      const std::string size = "/n:" + std::to_string(n);
      const Work w = v.backend == Backend::Cuda ? gpu_work(n) : work(n);
      const auto iters = std::max<std::int64_t>(
          1, std::llround(static_cast<double>(w.iterations) * iter_scale));
      for (const Pile kind : piles) {
        auto* bm = benchmark::RegisterBenchmark(
            (std::string(pile_name(kind)) + "/" + v.name() + method_tag + size).c_str(), pile_case,
            v, kind, n, w.steps_per_iteration);
        bm->Iterations(iters)->UseRealTime()->MeasureProcessCPUTime()->Unit(
            benchmark::kMillisecond);
        if (n >= 1000000 && large_reps > 0) bm->Repetitions(large_reps);
      }
      if (!frames) continue;
      // dense_pile's frames keep their names of before; another pile's carry its name.
      for (const Pile kind : piles)
        for (const bool contacts : {false, true}) {
          const std::string pile =
              kind == Pile::Dense ? std::string() : std::string(pile_name(kind)) + "/";
          auto* fb = benchmark::RegisterBenchmark(
              (std::string(contacts ? "frame_with_contacts/" : "frame/") + pile + v.name() + size)
                  .c_str(),
              snapshot_case, v, kind, n, contacts);
          fb->Iterations(3)->UseRealTime()->Unit(benchmark::kMillisecond);
        }
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
