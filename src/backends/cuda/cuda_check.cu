#include "backends/cuda/cuda_check.cuh"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <string>

namespace tridem::cuda {

void throw_cuda_error(cudaError_t error, const char* call, const char* file, int line) {
  std::string message = std::string("CUDA error ") + cudaGetErrorName(error) + " (" +
                        cudaGetErrorString(error) + ") in " + call + " at " + file + ":" +
                        std::to_string(line);
  if (error == cudaErrorMemoryAllocation)
    message += "; the GPU is out of memory: run fewer particles, precision = \"" +
               std::string(precision_name(Precision::Float)) + "\", or another backend";
  else if (error == cudaErrorNoDevice || error == cudaErrorInsufficientDriver)
    message += "; no usable GPU: use backend = \"" + std::string(backend_name(Backend::Cpu)) +
               "\" or \"" + std::string(backend_name(Backend::OpenMP)) + "\"";
  else
    message += "; the GPU state of this run is lost";
  throw RunError(message);
}

}  // namespace tridem::cuda
