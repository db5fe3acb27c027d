#pragma once
// Tests that run on every backend: a TEST_P over tridem::Backend, instantiated once per
// backend. Instantiate the CUDA one with the prefix Gpu, so that CTest labels it `gpu`:
//
//   INSTANTIATE_TEST_SUITE_P(Cpu, Suite, ::testing::Values(Backend::Cpu));
//   INSTANTIATE_TEST_SUITE_P(Gpu, Suite, ::testing::Values(Backend::Cuda));
//
// Where no GPU is usable, the CUDA instances skip themselves in SetUp, with the reason;
// GoogleTest then does not run the test body. No name generator on purpose: GoogleTest
// names the instances Suite.Test/0 and prints the value with PrintTo below, which
// gtest_discover_tests turns into the CTest name Gpu/Suite.Test/cuda (with a custom name
// the CTest name would keep a "# GetParam() = ..." tail).
#include "support/gpu.hpp"
#include "tridem/scene.hpp"

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

class BackendTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    if (GetParam() == Backend::Cuda) TRIDEM_SKIP_WITHOUT_GPU();
  }
};

}  // namespace tridem::test
