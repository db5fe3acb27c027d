#pragma once
// GPU tests skip themselves, with the reason, where the CUDA backend cannot run.
#include "backends/cuda/cuda_backend.hpp"

#include <gtest/gtest.h>
#include <string>

#define TRIDEM_SKIP_WITHOUT_GPU()                                   \
  do {                                                             \
    std::string tridem_reason;                                     \
    if (!::tridem::cuda_available(&tridem_reason))                 \
      GTEST_SKIP() << "no GPU for the CUDA backend: " << tridem_reason; \
  } while (0)
