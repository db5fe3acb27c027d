#include "backends/cuda/domain_assignment.cuh"

#include "backends/cuda/assignment_kernels.cuh"
#include "backends/cuda/sorted_ranges.cuh"

#include <algorithm>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_scan.cuh>

namespace tridem::cuda {

namespace {

constexpr int kBlock = 256;

int blocks(long long items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

/// Grows a device buffer to hold `items` (with headroom); keeps nothing.
template <class T>
void reserve(DeviceBuffer<T>& b, std::size_t items) {
  if (b.size() < items) b.allocate(items + items / 5 + 16);
}

/// Copies a host vector to a device buffer grown to hold it.
template <class T>
void upload(DeviceBuffer<T>& b, const std::vector<T>& host, cudaStream_t stream) {
  reserve(b, host.size());
  if (!host.empty())
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(b.data(), host.data(), host.size() * sizeof(T),
                                      cudaMemcpyHostToDevice, stream));
}

}  // namespace

template <class Real>
DomainAssignment<Real>::DomainAssignment(const std::vector<std::uint8_t>& small,
                                         cudaStream_t stream)
    : n_(static_cast<int>(small.size())), stream_(stream) {
  small_.upload(small);
  const auto n = static_cast<std::size_t>(n_);
  for (auto* b : {&owner_, &last_owner_, &owner_key_, &sorted_owner_key_, &index_, &owned_})
    b->allocate(std::max<std::size_t>(n, 1));
  band_count_.allocate(n + 1);
  band_position_.allocate(n + 1);
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(band_count_.data(), 0, band_count_.bytes(), stream_));
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(last_owner_.data(), 0xff, last_owner_.bytes(), stream_));
  largest_.allocate(1);
  migrations_.allocate(1);
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(migrations_.data(), 0, migrations_.bytes(), stream_));
  readback_.allocate(2);
}

template <class Real>
void DomainAssignment<Real>::size_for_domains(int domains) {
  domains_ = domains;
  const auto k = static_cast<std::size_t>(domains);
  reserve(hull_, k);
  reserve(staged_, k);
  reserve(owned_offset_, k + 1);
  reserve(member_offset_, k + 1);
}

template <class Real>
void DomainAssignment<Real>::take_from_host(const Decomposition<Real>& d) {
  const DomainMap m = d.map();
  origin_x_ = m.origin_x;
  origin_y_ = m.origin_y;
  cell_ = m.cell;
  rows_ = m.rows;
  upload(row_begin_, std::vector<std::int64_t>(m.row_begin, m.row_begin + m.rows), stream_);
  upload(row_first_, std::vector<int>(m.row_first, m.row_first + m.rows + 1), stream_);
  upload(col_begin_, std::vector<std::int64_t>(m.col_begin, m.col_begin + d.count()), stream_);
  size_for_domains(d.count());
  upload(owned_offset_, d.owned_offset(), stream_);
  upload(owned_, d.owned_list(), stream_);
  upload(member_offset_, d.member_offset(), stream_);
  upload(members_, d.member_list(), stream_);
  upload(owner_, d.owners(), stream_);
  largest_seen_ = std::max(largest_seen_, d.stats().max_members);
}

template <class Real>
void DomainAssignment<Real>::sort(const int* keys_in, int* keys_out, const int* values_in,
                                  int* values_out, int items, int domains) {
  int bits = 1;
  while (bits < 31 && (1ll << bits) <= domains) ++bits;  // keys go up to `domains`
  std::size_t bytes = 0;
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys_in, keys_out, values_in,
                                                    values_out, items, 0, bits, stream_));
  reserve(temp_, bytes);
  bytes = temp_.size();
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp_.data(), bytes, keys_in, keys_out,
                                                    values_in, values_out, items, 0, bits,
                                                    stream_));
}

template <class Real>
bool DomainAssignment<Real>::assign(const ParticleArrays<Real>& p, int capacity,
                                    const physics::PeriodicFrame* periodic) {
  if (periodic && extent_.size() == 0) extent_.allocate(1);
  const AssignmentView<Real> v{
      n_,
      domains_,
      {origin_x_, origin_y_, cell_, rows_, row_begin_.data(), row_first_.data(), col_begin_.data()},
      small_.data(),
      p.x,
      p.y,
      p.lo_x,
      p.lo_y,
      p.hi_x,
      p.hi_y,
      periodic ? *periodic : physics::PeriodicFrame{},
      periodic ? extent_.data() : nullptr};
  // Owners, then the owned lists: particles sorted by owner (stable: ascending in each).
  owner_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(v, owner_.data(), owner_key_.data(),
                                                          index_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("owner_kernel");
  sort(owner_key_.data(), sorted_owner_key_.data(), index_.data(), owned_.data(), n_, domains_);
  range_start_kernel<<<blocks(domains_ + 1), kBlock, 0, stream_>>>(
      sorted_owner_key_.data(), n_, domains_, owned_offset_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("range_start_kernel (owned)");
  hull_kernel<Real><<<blocks(domains_), kBlock, 0, stream_>>>(v, owned_offset_.data(),
                                                               owned_.data(), hull_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("hull_kernel");
  if (periodic) {
    extent_kernel<Real><<<1, 256, 0, stream_>>>(hull_.data(), domains_, extent_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("extent_kernel");
  }
  // Bands: counted per particle and per sub-domain, placed by a scan.
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(staged_.data(), 0, staged_.bytes(), stream_));
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(largest_.data(), 0, sizeof(int), stream_));
  band_count_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(v, hull_.data(), band_count_.data(),
                                                               staged_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("band_count_kernel");
  std::size_t bytes = 0;
  TRIDEM_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, bytes, band_count_.data(),
                                                  band_position_.data(), n_ + 1, stream_));
  reserve(temp_, bytes);
  bytes = temp_.size();
  TRIDEM_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.data(), bytes, band_count_.data(),
                                                  band_position_.data(), n_ + 1, stream_));
  largest_staged_kernel<<<blocks(domains_), kBlock, 0, stream_>>>(staged_.data(), domains_,
                                                                   largest_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("largest_staged_kernel");
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(readback_.data(), band_position_.data() + n_, sizeof(int),
                                    cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(readback_.data() + 1, largest_.data(), sizeof(int),
                                    cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  const int memberships = readback_.data()[0], largest = readback_.data()[1];
  if (largest > capacity) return false;
  largest_seen_ = std::max(largest_seen_, largest);
  const auto m = static_cast<std::size_t>(memberships);
  for (auto* b : {&members_, &band_key_, &sorted_band_key_, &band_value_}) reserve(*b, m);
  band_fill_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(
      v, hull_.data(), band_position_.data(), band_key_.data(), band_value_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("band_fill_kernel");
  sort(band_key_.data(), sorted_band_key_.data(), band_value_.data(), members_.data(),
       memberships, domains_);
  range_start_kernel<<<blocks(domains_ + 1), kBlock, 0, stream_>>>(
      sorted_band_key_.data(), memberships, domains_, member_offset_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("range_start_kernel (members)");
  return true;
}

template <class Real>
void DomainAssignment<Real>::count_migrations() {
  migration_kernel<<<blocks(n_), kBlock, 0, stream_>>>(n_, owner_.data(), last_owner_.data(),
                                                       migrations_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("migration_kernel");
}

template <class Real>
std::int64_t DomainAssignment<Real>::migrations() const {
  unsigned long long count = 0;
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(&count, migrations_.data(), sizeof count,
                                    cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  return static_cast<std::int64_t>(count);
}

template class DomainAssignment<float>;
template class DomainAssignment<double>;

}  // namespace tridem::cuda
