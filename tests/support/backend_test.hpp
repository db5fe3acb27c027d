#pragma once
// Tests that run on every backend: a TEST_P over test::SolverChoice (a backend, a method
// and a precision), instantiated once per choice. Instantiate the CUDA ones with the prefix Gpu, so
// that CTest labels them `gpu`:
//
//   INSTANTIATE_TEST_SUITE_P(Cpu, Suite, ::testing::Values(Backend::Cpu));
//   INSTANTIATE_TEST_SUITE_P(Gpu, Suite, ::testing::Values(Backend::Cuda));
//
// or TRIDEM_INSTANTIATE_SOLVERS(Suite) for both backends with the cell grid and with the
// paper's single-domain and decomposition methods, in double, and with the grid and the
// decomposition in float (the mixed mode: double state, float pairs). The float axis
// takes the grid (the method runs at scale) and the decomposition (its contact test reads
// the pair frame through other code: sub-domain staging); single-domain shares that test
// with the decomposition and is left out to keep the suites' time down.
//
// Where no GPU is usable, the CUDA instances skip themselves in SetUp, with the reason;
// GoogleTest then does not run the test body. No name generator on purpose: GoogleTest
// names the instances Suite.Test/0 and prints the value with PrintTo below, which
// gtest_discover_tests turns into the CTest name Gpu/Suite.Test/cuda (with a custom name
// the CTest name would keep a "# GetParam() = ..." tail).
#include "support/gpu.hpp"
#include "tridem/scene.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <ostream>

namespace tridem {

/// How GoogleTest prints a Backend (found by argument-dependent lookup).
inline void PrintTo(Backend backend, std::ostream* os) { *os << backend_name(backend); }

}  // namespace tridem

namespace tridem::test {

/// What a test runs on. Made from a Backend alone, it takes the cell grid in double.
struct SolverChoice {
  Backend backend = Backend::Cpu;
  Method method = Method::Grid;
  Precision precision = Precision::Double;

  SolverChoice(Backend b, Method m = Method::Grid, Precision p = Precision::Double)  // NOLINT
      : backend(b), method(m), precision(p) {}

  /// The scene set to run on this choice: backend, method and precision are settings of
  /// the scene, its one description of the run.
  Scene applied_to(Scene s) const {
    s.simulation.backend = backend;
    s.simulation.method = method;
    s.simulation.precision = precision;
    return s;
  }
};

/// A solver of the scene on the choice.
inline std::unique_ptr<Solver> solver_for(const Scene& s, const SolverChoice& choice,
                                          const SolverConfig& config = {}) {
  return make_solver(choice.applied_to(s), config);
}

/// backend = auto, with the choice's method and precision, takes the GPU for the scene.
inline void expect_auto_backend_takes_the_gpu(Scene s, const SolverChoice& choice) {
  s.simulation.backend = Backend::Auto;
  s.simulation.method = choice.method;
  s.simulation.precision = choice.precision;
  auto solver = make_solver(s, {});
  EXPECT_NE(solver->description().find(backend_name(Backend::Cuda)), std::string::npos)
      << solver->description();
}

/// "cuda", "cpu-single-domain" for another method than the grid, "cpu-float" or
/// "cuda-decomposition-float" in float (the CTest name's tail).
inline void PrintTo(const SolverChoice& c, std::ostream* os) {
  PrintTo(c.backend, os);
  if (c.method != Method::Grid) *os << "-" << method_name(c.method);
  if (c.precision == Precision::Float) *os << "-float";
}

/// A tolerance for the choice's precision: `in_double` where pairs are computed in double,
/// `in_float` where they are computed in float (the state is double in both). Each test
/// says why its float value is what float rounding allows.
inline double tolerance(const SolverChoice& c, double in_double, double in_float) {
  return c.precision == Precision::Float ? in_float : in_double;
}

class BackendTest : public ::testing::TestWithParam<SolverChoice> {
 protected:
  void SetUp() override {
    if (GetParam().backend == Backend::Cuda) TRIDEM_SKIP_WITHOUT_GPU();
  }
};

}  // namespace tridem::test

/// Every method on one backend in double; the grid and the decomposition in float.
#define TRIDEM_SOLVER_CHOICES(backend)                                                       \
  ::testing::Values(::tridem::test::SolverChoice(backend),                                  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::SingleDomain),  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::Decomposition), \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::Grid,           \
                                                 ::tridem::Precision::Float),               \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::Decomposition,  \
                                                 ::tridem::Precision::Float))

#define TRIDEM_INSTANTIATE_SOLVERS(Suite)                                         \
  INSTANTIATE_TEST_SUITE_P(Cpu, Suite, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cpu)); \
  INSTANTIATE_TEST_SUITE_P(Gpu, Suite, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cuda))

/// Every method on one backend, in double only.
#define TRIDEM_DOUBLE_SOLVER_CHOICES(backend)                                                \
  ::testing::Values(::tridem::test::SolverChoice(backend),                                  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::SingleDomain),  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::Decomposition))

/// For suites of friction-held statics on walls much larger than their grains: in float
/// such a wall is resolved only to ε·(wall size) inside pair_force (per cent of the contact
/// force at those scenes' penetrations) and friction slips lose creep increments, so a
/// block that holds in double creeps (docs/model.md, "Precision"): checked in double.
#define TRIDEM_INSTANTIATE_SOLVERS_IN_DOUBLE(Suite)                                      \
  INSTANTIATE_TEST_SUITE_P(Cpu, Suite, TRIDEM_DOUBLE_SOLVER_CHOICES(::tridem::Backend::Cpu)); \
  INSTANTIATE_TEST_SUITE_P(Gpu, Suite, TRIDEM_DOUBLE_SOLVER_CHOICES(::tridem::Backend::Cuda))
