#pragma once
// Tests that run on every backend: a TEST_P over test::SolverChoice (a backend and a
// method), instantiated once per choice. Instantiate the CUDA ones with the prefix Gpu, so
// that CTest labels them `gpu`:
//
//   INSTANTIATE_TEST_SUITE_P(Cpu, Suite, ::testing::Values(Backend::Cpu));
//   INSTANTIATE_TEST_SUITE_P(Gpu, Suite, ::testing::Values(Backend::Cuda));
//
// or TRIDEM_INSTANTIATE_SOLVERS(Suite) for both backends with the cell grid and with the
// paper's single-domain and decomposition methods.
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
#include <ostream>

namespace tridem {

/// How GoogleTest prints a Backend (found by argument-dependent lookup).
inline void PrintTo(Backend backend, std::ostream* os) {
  switch (backend) {
    case Backend::Auto: *os << "auto"; return;
    case Backend::Cpu: *os << "cpu"; return;
    case Backend::OpenMP: *os << "openmp"; return;
    case Backend::Cuda: *os << "cuda"; return;
  }
  *os << "backend" << static_cast<int>(backend);
}

}  // namespace tridem

namespace tridem::test {

/// What a test runs on. Made from a Backend alone, it takes the cell grid.
struct SolverChoice {
  Backend backend = Backend::Cpu;
  Method method = Method::Grid;

  SolverChoice(Backend b, Method m = Method::Grid) : backend(b), method(m) {}  // NOLINT

  SolverConfig config() const {
    SolverConfig c;
    c.backend = backend;
    c.method = method;
    return c;
  }
};

/// "cuda", or "cpu-single-domain" for another method than the grid (the CTest name's tail).
inline void PrintTo(const SolverChoice& c, std::ostream* os) {
  PrintTo(c.backend, os);
  if (c.method != Method::Grid) *os << "-" << method_name(c.method);
}

class BackendTest : public ::testing::TestWithParam<SolverChoice> {
 protected:
  void SetUp() override {
    if (GetParam().backend == Backend::Cuda) TRIDEM_SKIP_WITHOUT_GPU();
  }
};

}  // namespace tridem::test

/// Every method on one backend.
#define TRIDEM_SOLVER_CHOICES(backend)                                                       \
  ::testing::Values(::tridem::test::SolverChoice(backend),                                  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::SingleDomain),  \
                    ::tridem::test::SolverChoice(backend, ::tridem::Method::Decomposition))

#define TRIDEM_INSTANTIATE_SOLVERS(Suite)                                         \
  INSTANTIATE_TEST_SUITE_P(Cpu, Suite, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cpu)); \
  INSTANTIATE_TEST_SUITE_P(Gpu, Suite, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cuda))
