#pragma once
// Every CUDA call is checked: a failure becomes a RunError that names the call, the
// error and what it means for the run, never a crash or a silent wrong number.
#include <cuda_runtime.h>

namespace tridem::cuda {

[[noreturn]] void throw_cuda_error(cudaError_t error, const char* call, const char* file,
                                   int line);

inline void check(cudaError_t error, const char* call, const char* file, int line) {
  if (error != cudaSuccess) throw_cuda_error(error, call, file, line);
}

}  // namespace tridem::cuda

#define TRIDEM_CUDA_CHECK(call) ::tridem::cuda::check((call), #call, __FILE__, __LINE__)
/// After a kernel launch: a bad configuration shows here, a fault at the next sync.
#define TRIDEM_CUDA_CHECK_LAUNCH(kernel) \
  ::tridem::cuda::check(cudaGetLastError(), "launch of " kernel, __FILE__, __LINE__)
