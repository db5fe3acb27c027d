#pragma once
// The CUDA solver's per-particle fields (tridem/particle_fields.hpp) in device memory, and
// the view its kernels receive.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/device_views.cuh"
#include "core/particle_columns.hpp"

namespace tridem::cuda {

template <class Real>
struct ParticleBuffers {
  template <class T>
  using Column = DeviceBuffer<T>;
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_COLUMN_ACCESSOR)

  /// Every field at its initial value for the model's particles.
  void upload_initial(const ParticleModel& model) {
    for_each_gpu_particle_field([&](auto field) {
      for_each_array(column(field),
                     [&](auto& b, int k) { b.upload(initial_column<Real>(field, model, k)); });
    });
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
