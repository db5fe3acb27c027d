#pragma once
// The CUDA solver's per-particle fields (tridem/particle_fields.hpp) in device memory, and
// the view its kernels receive.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/device_views.cuh"
#include "core/particle_columns.hpp"
#include "tridem/error.hpp"

#include <type_traits>

namespace tridem::cuda {

template <class Real>
struct ParticleBuffers {
  template <class T>
  using Column = DeviceBuffer<T>;
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_COLUMN_ACCESSOR)

  /// Every field at its initial value for the model's particles. The values are filled on
  /// the host's threads straight into `staging` (page-locked: copied at the bus's speed,
  /// where a pageable vector per array was copied through the driver's own bounce buffers,
  /// issue 12's set-up of a 10^7 run); an array that does not fit beside those in flight
  /// waits for them. The staging holds the snapshots' six doubles a particle and more, so
  /// any one array fits.
  void upload_initial(const ParticleModel& model, const PinnedBuffer<unsigned char>& staging,
                      cudaStream_t stream) {
    const std::size_t n = model.size();
    std::size_t at = 0;
    for_each_gpu_particle_field([&](auto field) {
      for_each_array(column(field), [&](auto& b, int k) {
        using T = typename std::decay_t<decltype(b)>::value_type;
        const std::size_t bytes = n * sizeof(T);
        b.allocate(n);
        if (n == 0) return;
        if (bytes > staging.size())
          throw RunError("internal error: the snapshot staging cannot hold a particle array");
        if (at + bytes > staging.size()) {
          TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
          at = 0;
        }
        T* host = reinterpret_cast<T*>(staging.data() + at);
        fill_initial_column<Real>(field, model, k, host);
        TRIDEM_CUDA_CHECK(cudaMemcpyAsync(b.data(), host, bytes, cudaMemcpyHostToDevice, stream));
        at += (bytes + 7) / 8 * 8;  // every array 8-byte aligned
      });
    });
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
  }

  ParticleArrays<Real> view(int n) const {
    ParticleArrays<Real> p{};
    p.n = n;
    for_each_gpu_particle_field([&](auto field) {
      for_each_array(p.column(field),
                     [&](auto& pointer, int k) { pointer = array_at(column(field), k).data(); });
    });
    return p;
  }
};

}  // namespace tridem::cuda
