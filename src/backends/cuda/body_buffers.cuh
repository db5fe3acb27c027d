#pragma once
// The CUDA solver's per-body and per-member fields (tridem/body_fields.hpp) in device
// memory, and the view its body kernels receive; allocated only for scenes with bodies of
// several triangles (otherwise empty, and no kernel reads them).
#include "backends/cuda/device_buffer.cuh"
#include "core/particle_columns.hpp"
#include "tridem/body_fields.hpp"

namespace tridem::cuda {

/// Every body and member field as a device pointer: `const std::int64_t* body_first`,
/// `double* body_x`, `const std::int32_t* member_body`, ... (Model fields const).
struct BodyArrays {
  int n;  ///< bodies
  TRIDEM_BODY_FIELDS(TRIDEM_DECLARE_BODY_POINTERS)
  TRIDEM_MEMBER_FIELDS(TRIDEM_DECLARE_BODY_POINTERS)

  TRIDEM_BODY_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)
  TRIDEM_MEMBER_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)
};

struct BodyBuffers {
  template <class T>
  using Column = DeviceBuffer<T>;
  TRIDEM_BODY_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_MEMBER_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_BODY_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)
  TRIDEM_MEMBER_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)

  /// Every field at its initial value for the bodies of `m`, whose members are `triangles`.
  void upload_initial(const BodyModel& m, std::size_t triangles) {
    for_each_body_field(
        [&](auto field) { column(field).upload(initial_body_column(field, m, m.size())); });
    for_each_member_field(
        [&](auto field) { column(field).upload(initial_body_column(field, m, triangles)); });
  }

  /// All of them copied to the host (snapshots: synchronous, output steps only).
  void download(BodyColumns& to, std::size_t bodies, std::size_t triangles) const {
    for_each_body_field([&](auto field) {
      to.column(field).resize(bodies);
      column(field).download(to.column(field));
    });
    for_each_member_field([&](auto field) {
      to.column(field).resize(triangles);
      column(field).download(to.column(field));
    });
  }

  BodyArrays view(int bodies) const {
    BodyArrays b{};
    b.n = bodies;
    for_each_body_field([&](auto field) { b.column(field) = column(field).data(); });
    for_each_member_field([&](auto field) { b.column(field) = column(field).data(); });
    return b;
  }
};

}  // namespace tridem::cuda
