#pragma once
// The decomposition's owners and lists on the GPU. The host computes the borders (first
// grouping, and border moves when a sub-domain overflows: Decomposition); with those
// borders the GPU finds, every step, each particle's owner, the hulls and the overlap
// bands (assignment_kernels.cuh), so that only an overflow brings the state to the host.
// The lists equal the host's for the same borders: the same DomainMap code, exact min and
// max, stable sorts.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/device_views.cuh"
#include "decomposition/decomposition.hpp"

#include <cstdint>
#include <vector>

namespace tridem::cuda {

template <class Real>
class DomainAssignment {
 public:
  DomainAssignment(const std::vector<std::uint8_t>& small, cudaStream_t stream);

  /// Borders, owners and lists as the host has them after its update.
  void take_from_host(const Decomposition<Real>& d);
  /// Owners, hulls and bands on the GPU with the borders last taken from the host; false
  /// (lists unusable) when some sub-domain would stage more than `capacity` particles.
  /// In a periodic cell (`periodic`, the frame of this step) the bands take the images of
  /// the particles across the boundaries, as the host's do. Synchronises once, to learn
  /// the number of memberships and the largest sub-domain.
  bool assign(const ParticleArrays<Real>& p, int capacity,
              const physics::PeriodicFrame* periodic = nullptr);
  /// Counts the particles whose owner changed since the last call.
  void count_migrations();

  const int* owned_offset() const { return owned_offset_.data(); }
  const int* owned() const { return owned_.data(); }
  const int* member_offset() const { return member_offset_.data(); }
  const int* members() const { return members_.data(); }
  int largest_staged() const { return largest_seen_; }
  std::int64_t migrations() const;

 private:
  void size_for_domains(int domains);
  void sort(const int* keys_in, int* keys_out, const int* values_in, int* values_out,
            int items, int domains);

  int n_;
  cudaStream_t stream_;
  int domains_ = 0;
  double origin_x_ = 0, origin_y_ = 0, cell_ = 1;
  int rows_ = 1;
  int largest_seen_ = 0;
  DeviceBuffer<std::uint8_t> small_;
  // Borders (DomainMap).
  DeviceBuffer<std::int64_t> row_begin_, col_begin_;
  DeviceBuffer<int> row_first_;
  // Per particle.
  DeviceBuffer<int> owner_, last_owner_, owner_key_, sorted_owner_key_, index_;
  DeviceBuffer<int> band_count_, band_position_;  ///< n + 1
  // Per sub-domain.
  DeviceBuffer<Hull<Real>> hull_;
  DeviceBuffer<Hull<double>> extent_;  ///< of the hulls, in a periodic cell
  DeviceBuffer<int> staged_, owned_offset_, member_offset_;
  // Lists, and the memberships they are sorted from.
  DeviceBuffer<int> owned_, members_, band_key_, sorted_band_key_, band_value_;
  DeviceBuffer<std::uint8_t> temp_;  ///< CUB scratch
  DeviceBuffer<int> largest_;
  DeviceBuffer<unsigned long long> migrations_;
  PinnedBuffer<int> readback_;  ///< memberships, largest sub-domain
};

}  // namespace tridem::cuda
