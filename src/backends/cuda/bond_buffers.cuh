#pragma once
// The CUDA solver's cohesive bonds (docs/fracture.md) in device memory: the columns of
// core/bond_columns.hpp as DeviceBuffers, uploaded once from the host's initial columns,
// a per-bond scratch for the energy of the last step, and a host copy whose model columns
// stay as uploaded and whose state columns (damage, broken, released energy) are brought
// back for snapshots and checkpoints. Allocated only for bonded scenes (otherwise empty,
// and no kernel reads them).
#include "backends/cuda/device_buffer.cuh"
#include "core/bond_columns.hpp"

namespace tridem::cuda {

template <class Real>
struct BondBuffers {
  BondColumns<DeviceBuffer, Real> d;
  DeviceBuffer<double> elastic;  ///< each bond's elastic energy of the last step (energy())
  mutable HostBondColumns<Real> host;

  std::size_t size() const { return host.size(); }

  /// Every column of `initial` to the GPU (and kept as the host copy).
  void upload(HostBondColumns<Real> initial) {
    host = std::move(initial);
    d.for_each_column_with(host, [](auto& to, const auto& from, bool) { to.upload(from); });
    elastic.allocate(host.size());
  }

  /// The state columns into the host copy (synchronous: output steps and checkpoints).
  const HostBondColumns<Real>& download_state() const {
    d.for_each_column_with(host, [](const auto& from, auto& to, bool state) {
      if (state) from.download(to);
    });
    return host;
  }

  /// The host copy's state columns to the GPU (a restart).
  void upload_state() {
    d.for_each_column_with(host, [](auto& to, const auto& from, bool state) {
      if (state) to.upload(from);
    });
  }

  physics::BondArrays<Real> view() const { return d.view(size()); }
};

}  // namespace tridem::cuda
