// The experiments of the seed paper (Zhang, Quigley & Chan, §4–5) rerun with tridem's
// implementations of its two GPU designs, and the same problems with tridem's own cell grid.
// Each case is named EXPERIMENT/BACKEND/METHOD/VARIANT/n:N/k:K; bench/paper/make_figures.py
// turns the JSON (--benchmark_out) into the tables and figures of bench/results/paper/.
//
//   table3     256 triangles: time per step on the GPU and on one CPU core, and the
//              host–device transfer of the state (load_state up, snapshot down)
//   fig12      the whole job (solver set-up with its upload, k steps, the state back)
//              for k = 1..1000: the speed-up against the number of steps
//   fig19      time for 100 steps against n, 1D decomposition, CPU and GPU
//   fig20      2D decompositions with rows of different heights against n, GPU
//   fig21      2D decomposition against n on the problems of fig19, CPU and GPU
//   prefilter  single-domain with and without the bounding-box pre-filter, on sparse,
//              medium and dense packings
// and every problem again with method = grid.
//
// Flags: --experiments=LIST (default all), --max_n=N (GPU sizes, default 1048576),
// --cpu_max_n=N (CPU sizes, default 16384), plus Google Benchmark's.
#include "bench_flags.hpp"
#include "backends/cuda/cuda_backend.hpp"
#include "tridem/generate.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using tridem::Backend;
using tridem::DecompositionLayout;
using tridem::Method;

/// How a case finds its pairs.
struct Design {
  Method method = Method::Grid;
  DecompositionLayout layout = DecompositionLayout::Strips;
  int rows = 0, columns = 0;
  /// 2D: rows of this many cells of size L (the paper's Fig. 20 shapes are sub-domain sizes
  /// in cells); the row count then follows from the problem's height. 0: `rows`.
  int row_cells = 0;
  bool prefilter = true;

  std::string name() const {
    const char* layout_tag = layout == DecompositionLayout::Strips ? "-1d" : "-2d";
    const std::string shape =
        row_cells > 0 ? fmt::format("-h{}", row_cells)
                      : (rows > 0 || columns > 0 ? fmt::format("-{}x{}", rows, columns) : std::string());
    return fmt::format("{}{}{}", tridem::method_name(method),
                       method == Method::Decomposition ? layout_tag + shape : std::string(),
                       prefilter ? "" : "-noprefilter");
  }
};

/// The problems: the paper's densely initialised system as a square pile, the same as a
/// layer 32 lattice rows high (so that a 1D strip of capacity 256 can hold a whole column),
/// and loose random packings for the pre-filter question.
enum class Problem { Square, Layer, Dense, Medium, Sparse };

const char* problem_name(Problem p) {
  switch (p) {
    case Problem::Square: return "square";
    case Problem::Layer: return "layer";
    case Problem::Dense: return "dense";
    case Problem::Medium: return "medium";
    case Problem::Sparse: return "sparse";
  }
  return "?";
}

tridem::Scene packing(std::size_t n, double gap) {
  tridem::Scene s = tridem::dense_pile(16);
  s.triangles.clear();
  tridem::RandomPackingSpec spec;
  spec.size = 0.01;
  spec.gap = gap;
  spec.seed = 3;
  spec.irregularity = 0.3;
  const double pitch = 2 * spec.size / std::sqrt(3.0) * (1 + gap);
  const double side = std::ceil(std::sqrt(static_cast<double>(n))) * pitch;
  spec.region_max = {side, side};
  spec.count = n;
  s.triangles = tridem::generate_random(spec);
  return s;
}

tridem::Scene problem(Problem p, std::size_t n) {
  constexpr double kLayerRows = 32, kRowHeight = 0.8660254037844386;
  switch (p) {
    case Problem::Square: return tridem::dense_pile(n);
    case Problem::Layer: {
      // n = 2·(width/size)·rows: width over height = n / (2·rows²·row height).
      const double aspect = static_cast<double>(n) / (2 * kLayerRows * kLayerRows * kRowHeight);
      return tridem::dense_pile(n, 0.01, aspect);
    }
    case Problem::Dense: return packing(n, 0.02);
    case Problem::Medium: return packing(n, 0.5);
    case Problem::Sparse: return packing(n, 3.0);
  }
  return {};
}

struct Case {
  Backend backend;
  Design design;
  Problem problem;
  std::size_t n;
};

/// The case's scene with its backend and its method's settings.
tridem::Scene scene_for(const Case& c) {
  tridem::Scene s = problem(c.problem, c.n);
  s.simulation.backend = c.backend;
  s.simulation.method = c.design.method;
  s.simulation.bbox_prefilter = c.design.prefilter;
  s.simulation.decomposition.layout = c.design.layout;
  s.simulation.decomposition.rows = c.design.rows;
  if (c.design.row_cells > 0) {
    // Rows of row_cells cells of L (the longest free edge) over the height of the grains.
    double lo = 1e300, hi = -1e300, longest = 0;
    for (const tridem::TriangleSpec& t : s.triangles) {
      if (t.motion != tridem::Motion::Free) continue;
      for (int k = 0; k < 3; ++k) {
        lo = std::min(lo, t.vertices[k].y);
        hi = std::max(hi, t.vertices[k].y);
        const tridem::Vec2d e = t.vertices[(k + 1) % 3] - t.vertices[k];
        longest = std::max(longest, std::hypot(e.x, e.y));
      }
    }
    s.simulation.decomposition.rows =
        std::max(1, static_cast<int>(std::ceil((hi - lo) / (c.design.row_cells * longest))));
  }
  s.simulation.decomposition.columns = c.design.columns;
  return s;
}

/// A solver of scene_for(c) (whose settings name the backend and the method).
std::unique_ptr<tridem::Solver> make(const tridem::Scene& s) {
  return tridem::make_solver(s, tridem::SolverConfig{});
}

std::unique_ptr<tridem::Solver> make(const Case& c) { return make(scene_for(c)); }

void describe(benchmark::State& state, const tridem::Solver& solver) {
  const std::string stats = solver.statistics();
  state.SetLabel(solver.description() + (stats.empty() ? "" : "; " + stats));
  state.counters["triangles"] = static_cast<double>(solver.size());
}

template <class Body>
void guarded(benchmark::State& state, Body&& body) {
  try {
    body();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    for (auto _ : state) {
    }
  }
}

/// k steps per iteration of one solver, after two untimed steps (first touch, lists grown).
void steps_case(benchmark::State& state, Case c, std::int64_t k) {
  guarded(state, [&] {
    auto solver = make(c);
    solver->advance(2);
    for (auto _ : state) solver->advance(k);
    using benchmark::Counter;
    state.counters["s_per_step"] =
        Counter(static_cast<double>(k), Counter::kIsIterationInvariantRate | Counter::kInvert);
    describe(state, *solver);
  });
}

/// The state up to the solver (load_state) or back to the host (snapshot, no contacts).
void transfer_case(benchmark::State& state, Case c, bool upload) {
  guarded(state, [&] {
    auto solver = make(c);
    solver->advance(2);
    tridem::SolverState s;
    solver->save_state(s);
    tridem::Snapshot snap;
    for (auto _ : state) {
      if (upload)
        solver->load_state(s);
      else
        solver->snapshot(snap, false);
    }
    describe(state, *solver);
  });
}

/// The whole job of the paper's Fig. 12: set-up (the scene's data to the solver), k steps,
/// the final state back to the host. The scene itself is made before the clock starts:
/// generating a lattice is not part of the paper's job.
void job_case(benchmark::State& state, Case c, std::int64_t k) {
  guarded(state, [&] {
    const tridem::Scene scene = scene_for(c);
    tridem::Snapshot snap;
    // One untimed set-up first: the process's first GPU solver also creates the CUDA
    // context (tens of ms), which no later job pays.
    std::unique_ptr<tridem::Solver> solver = make(scene);
    for (auto _ : state) {
      solver = make(scene);
      solver->advance(k);
      solver->snapshot(snap, false);
    }
    describe(state, *solver);
  });
}

struct Limits {
  double max_n = 1048576, cpu_max_n = 16384;
  bool fits(Backend b, std::size_t n) const {
    return static_cast<double>(n) <= (b == Backend::Cuda ? max_n : cpu_max_n);
  }
};

std::string case_name(const char* experiment, const Case& c, const std::string& tail) {
  return fmt::format("{}/{}/{}/{}/n:{}{}", experiment, tridem::backend_name(c.backend),
                     c.design.name(), problem_name(c.problem), c.n, tail);
}

void add_steps(const char* experiment, const Case& c, std::int64_t k, int iterations,
               const Limits& limits) {
  if (!limits.fits(c.backend, c.n)) return;
  benchmark::RegisterBenchmark(case_name(experiment, c, fmt::format("/k:{}", k)).c_str(),
                               steps_case, c, k)
      ->Iterations(iterations)
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond);
}

const Backend kBackends[] = {Backend::Cpu, Backend::Cuda};

void register_all(const std::set<std::string>& experiments, const Limits& limits) {
  auto wanted = [&](const char* e) { return experiments.empty() || experiments.count(e) > 0; };
  const Design grid{}, single{Method::SingleDomain};
  const Design strips{Method::Decomposition, DecompositionLayout::Strips};
  const Design auto_2d{Method::Decomposition, DecompositionLayout::Grid};
  auto iterations = [](Backend b, std::size_t n) {
    return b == Backend::Cuda ? 20 : (n <= 1024 ? 5 : 1);
  };

  if (wanted("table3"))
    for (const Backend b : kBackends)
      for (const Design& d : {single, strips, grid}) {
        const Case c{b, d, Problem::Square, 256};
        add_steps("table3", c, 100, iterations(b, 256), limits);
        for (const bool up : {true, false})
          benchmark::RegisterBenchmark(
              case_name("table3", c, up ? "/upload" : "/download").c_str(), transfer_case, c, up)
              ->Iterations(200)
              ->UseRealTime()
              ->Unit(benchmark::kMicrosecond);
      }

  if (wanted("fig12"))
    for (const std::size_t n : {std::size_t{256}, std::size_t{4096}})
      for (const Backend b : kBackends)
        for (const std::int64_t k : {1, 10, 100, 1000}) {
          if (b == Backend::Cpu && n > 256 && k > 100) continue;  // minutes of O(n²) steps
          const Case c{b, single, Problem::Square, n};
          if (!limits.fits(b, n)) continue;
          benchmark::RegisterBenchmark(case_name("fig12", c, fmt::format("/k:{}", k)).c_str(),
                                       job_case, c, k)
              ->Iterations(b == Backend::Cuda ? 5 : 1)
              ->UseRealTime()
              ->Unit(benchmark::kMillisecond);
        }

  const std::size_t sizes[] = {256, 1024, 4096, 16384, 65536, 262144, 1048576};
  if (wanted("fig19") || wanted("fig21"))
    for (const std::size_t n : sizes)
      for (const Backend b : kBackends)
        for (const Design& d : {strips, auto_2d, grid})
          add_steps("fig19", {b, d, Problem::Layer, n}, 100, b == Backend::Cuda ? 3 : 1, limits);

  if (wanted("fig20"))
    for (const std::size_t n : {std::size_t{4096}, std::size_t{16384}, std::size_t{65536},
                                std::size_t{262144}, std::size_t{1048576}}) {
      // Sub-domain rows 3..8 cells high (auto: about square sub-domains). The paper's best,
      // 14 x 14 cells, held one particle per cell; a dense pile of triangles holds about 2.3
      // per cell of L, so 8 + 2 band cells are the most a row of capacity 256 takes.
      for (const int cells : {0, 3, 4, 6, 8}) {
        Design d = auto_2d;
        d.row_cells = cells;
        add_steps("fig20", {Backend::Cuda, d, Problem::Square, n}, 100, 3, limits);
      }
      add_steps("fig20", {Backend::Cuda, grid, Problem::Square, n}, 100, 3, limits);
    }

  if (wanted("prefilter"))
    for (const Problem p : {Problem::Sparse, Problem::Medium, Problem::Dense})
      for (const Backend b : kBackends)
        for (const std::size_t n : {std::size_t{1024}, std::size_t{16384}}) {
          if (b == Backend::Cpu && n > 1024) continue;
          for (const bool on : {true, false}) {
            Design d = single;
            d.prefilter = on;
            add_steps("prefilter", {b, d, p, n}, 10, b == Backend::Cuda ? 10 : 3, limits);
            Design dd = strips;
            dd.layout = DecompositionLayout::Grid;
            dd.prefilter = on;
            add_steps("prefilter", {b, dd, p, n}, 10, b == Backend::Cuda ? 10 : 3, limits);
          }
          add_steps("prefilter", {b, grid, p, n}, 10, b == Backend::Cuda ? 10 : 3, limits);
        }
}

}  // namespace

int main(int argc, char** argv) {
  using tridem::bench::parse_number;
  using tridem::bench::take_flag;
  Limits limits;
  if (auto v = take_flag(argc, argv, "max_n"); !v.empty())
    limits.max_n = parse_number("tridem_paper_bench", "max_n", v);
  if (auto v = take_flag(argc, argv, "cpu_max_n"); !v.empty())
    limits.cpu_max_n = parse_number("tridem_paper_bench", "cpu_max_n", v);
  std::set<std::string> experiments;
  std::istringstream list(take_flag(argc, argv, "experiments"));
  for (std::string e; std::getline(list, e, ',');)
    if (!e.empty()) experiments.insert(e);

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::AddCustomContext("cpu_model", tridem::bench::cpu_model());
  benchmark::AddCustomContext("gpu", tridem::cuda_device_description());
  benchmark::AddCustomContext("tridem_version", TRIDEM_VERSION);
  register_all(experiments, limits);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
