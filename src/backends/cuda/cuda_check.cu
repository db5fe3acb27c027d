#include "backends/cuda/cuda_check.cuh"
#include "tridem/error.hpp"

#include <string>

namespace tridem::cuda {

void throw_cuda_error(cudaError_t error, const char* call, const char* file, int line) {
  std::string message = std::string("CUDA error ") + cudaGetErrorName(error) + " (" +
                        cudaGetErrorString(error) + ") in " + call + " at " + file + ":" +
                        std::to_string(line);
  if (error == cudaErrorMemoryAllocation)
    message += "; the GPU is out of memory: run fewer particles, precision = \"float\", or "
               "another backend";
  else if (error == cudaErrorNoDevice || error == cudaErrorInsufficientDriver)
    message += "; no usable GPU: use backend = \"cpu\" or \"openmp\"";
  else
    message += "; the GPU state of this run is lost";
  throw RunError(message);
}

}  // namespace tridem::cuda
