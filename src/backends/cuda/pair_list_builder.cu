#include "backends/cuda/pair_list_builder.cuh"

#include "backends/cuda/broad_phase_kernels.cuh"
#include "backends/cuda/periodic_search.cuh"

#include "core/memory_estimate.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <algorithm>
#include <climits>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_scan.cuh>
#include <string>

namespace tridem::cuda {

namespace {

constexpr int kBlock = 256;

int blocks(long long items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

int bits_for(unsigned long long largest) {
  int b = 1;
  while (b < 32 && (1ull << b) <= largest) ++b;
  return b;
}

/// Cells at most: the CPU's cap of 4 per particle.
long long max_cells(int n) { return 4ll * n + 16; }

}  // namespace

template <class Real>
PairListBuilder<Real>::PairListBuilder(const std::vector<std::uint8_t>& small, Method method,
                                       Real cell, ContactFilter filter,
                                       std::size_t pair_capacity, cudaStream_t stream)
    : n_(static_cast<int>(small.size())),
      method_(method),
      cell_(cell),
      filter_(filter),
      stream_(stream) {
  beyond_ = static_cast<unsigned int>(max_cells(n_));
  cell_bits_ = bits_for(beyond_);
  particle_bits_ = bits_for(static_cast<unsigned long long>(n_));
  small_.upload(small);
  std::vector<int> large;
  for (int i = 0; i < n_; ++i)
    if (!small[i]) large.push_back(i);
  n_large_ = static_cast<int>(large.size());
  large_.upload(large);
  bounds_.allocate(1);
  grid_.allocate(1);
  init_bounds_kernel<Real><<<1, 1, 0, stream_>>>(bounds_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("init_bounds_kernel");
  const auto n = static_cast<std::size_t>(n_);
  cell_of_.allocate(n);
  sorted_cell_.allocate(n);
  index_.allocate(n);
  sorted_.allocate(n);
  cell_start_.allocate(static_cast<std::size_t>(beyond_));
  cell_end_.allocate(static_cast<std::size_t>(beyond_));
  row_count_.allocate(n + 1);
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(row_count_.data(), 0, row_count_.bytes(), stream_));
  for (auto* b : {&offset_, &old_offset_, &reverse_offset_}) {
    b->allocate(n + 1);
    TRIDEM_CUDA_CHECK(cudaMemsetAsync(b->data(), 0, b->bytes(), stream_));
  }
  total_.allocate(1);
  reserve_pairs(pair_capacity);
  clear_details();
}

template <class Real>
void PairListBuilder<Real>::reserve_pairs(std::size_t pairs) {
  pairs = std::max<std::size_t>(pairs, 1);
  if (pairs > static_cast<std::size_t>(INT_MAX))
    throw RunError("the pair list would need more than 2^31 pairs: too many particles for one GPU");
  refuse_unless_pairs_fit(pairs);
  // The old list is in phases_ while a build grows the slots (size_rows): it moves with
  // them; the other arrays are written whole before they are read.
  const std::size_t keep = static_cast<std::size_t>(old_count_);
  old_count_ = 0;
  auto grow = [pairs](auto& buffer) {
    if (buffer.size() < pairs) buffer.allocate(pairs);
  };
  grow(partner_);
  grow(slip_);
  grow(emitter_);
  grow(load_);
  grow(reverse_slot_);
  phases_.reserve(std::max(pairs, phases_.slots()), size_temp_storage(pairs), keep, stream_);
}

template <class Real>
void PairListBuilder<Real>::refuse_unless_pairs_fit(std::size_t pairs) const {
  const std::size_t have = partner_.size();
  if (pairs <= have) return;
  const Precision precision = kPrecisionOf<Real>;
  const std::size_t need = (pairs - have) * gpu_pair_bytes(precision);
  std::size_t free_bytes = 0, total_bytes = 0;
  TRIDEM_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  if (need > free_bytes)
    throw RunError("the pair list needs " + std::to_string(pairs) + " slots (its pairs and a " +
                   "fifth more), about " + mebibytes(need) +
                   " more of GPU memory, but the GPU has " + mebibytes(free_bytes) + " free of " +
                   mebibytes(total_bytes) + ": use " +
                   (precision == Precision::Double
                        ? "precision = \"" + std::string(precision_name(Precision::Float)) + "\", "
                        : std::string()) +
                   "fewer particles, a smaller skin, or backend = \"" +
                   std::string(backend_name(Backend::OpenMP)) + "\"");
}

template <class Real>
std::size_t PairListBuilder<Real>::size_temp_storage(std::size_t pairs) {
  std::size_t need = 0, bytes = 0;
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(
      nullptr, bytes, cell_of_.data(), sorted_cell_.data(), index_.data(), sorted_.data(), n_,
      0, cell_bits_, stream_));
  need = std::max(need, bytes);
  TRIDEM_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, bytes, row_count_.data(),
                                                  offset_.data(), n_ + 1, stream_));
  need = std::max(need, bytes);
  if (temp_.size() < need) temp_.allocate(need);
  // A size query (the arrays are not read): the reverse index's sort, whose scratch is
  // in phases_.
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(
      nullptr, bytes, partner_.data(), partner_.data(), reverse_slot_.data(), reverse_slot_.data(),
      static_cast<int>(pairs), 0, particle_bits_, stream_));
  return bytes;
}

template <class Real>
CandidateSearch<Real> PairListBuilder<Real>::search(const ParticleArrays<Real>& p) const {
  return {n_,
          method_ == Method::AllPairs,
          p.free,
          small_.data(),
          p.build_lo_x,
          p.build_lo_y,
          p.build_hi_x,
          p.build_hi_y,
          grid_.data(),
          cell_of_.data(),
          sorted_.data(),
          cell_start_.data(),
          cell_end_.data(),
          large_.data(),
          n_large_};
}

template <class Real>
SingleDomainSearch<Real> PairListBuilder<Real>::single_domain_search(
    const ParticleArrays<Real>& p) const {
  return {n_,
          p.free,
          small_.data(),
          {{p.rel_x[0], p.rel_x[1], p.rel_x[2]},
           {p.rel_y[0], p.rel_y[1], p.rel_y[2]},
           p.lo_x,
           p.lo_y,
           p.hi_x,
           p.hi_y,
           p.x,
           p.y},
          large_.data(),
          n_large_,
          filter_,
          physics::PeriodicFrame{}};
}

template <class Real>
void PairListBuilder<Real>::set_periodic(double sheared_slack) {
  periodic_ = true;
  sheared_slack_ = sheared_slack;
  periodic_grid_.allocate(1);
}

template <class Real>
void PairListBuilder<Real>::rebuild(const ParticleArrays<Real>& p, Real margin,
                                    const physics::PeriodicFrame& frame) {
  if (method_ == Method::SingleDomain) {
    // The paper's kernel: blocks of 64 threads, one per particle.
    SingleDomainSearch<Real> c = single_domain_search(p);
    c.frame = frame;
    if (periodic_)
      single_domain_rows<true>(c);
    else
      single_domain_rows<false>(c);
  } else {
    const CandidateSearch<Real> c = search(p);
    grow_boxes_kernel<Real>
        <<<blocks(n_), kBlock, 0, stream_>>>(p, small_.data(), margin, bounds_.data());
    TRIDEM_CUDA_CHECK_LAUNCH("grow_boxes_kernel");
    if (periodic_) {
      const PeriodicFinder<Real> find{
          c, PeriodicSearch{frame, p.x, p.y, periodic_grid_.data(), sheared_slack_}};
      if (method_ == Method::Grid) bin_periodic(find);
      fill_rows(find);
    } else {
      const GridFinder<Real> find{c};
      if (method_ == Method::Grid) bin(c);
      fill_rows(find);
    }
  }
  index_rows();
  ++builds_;
}

template <class Real>
template <bool kPeriodic>
void PairListBuilder<Real>::single_domain_rows(const SingleDomainSearch<Real>& c) {
  const int tiles = (n_ + kSingleDomainBlock - 1) / kSingleDomainBlock;
  single_domain_count_kernel<Real, kPeriodic>
      <<<tiles, kSingleDomainBlock, 0, stream_>>>(c, row_count_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("single_domain_count_kernel");
  size_rows();
  single_domain_fill_kernel<Real, kPeriodic>
      <<<tiles, kSingleDomainBlock, 0, stream_>>>(c, history());
  TRIDEM_CUDA_CHECK_LAUNCH("single_domain_fill_kernel");
}

template <class Real>
void PairListBuilder<Real>::bin(const CandidateSearch<Real>& c) {
  grid_kernel<Real><<<1, 1, 0, stream_>>>(bounds_.data(), cell_, max_cells(n_), grid_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("grid_kernel");
  cell_key_kernel<Real>
      <<<blocks(n_), kBlock, 0, stream_>>>(c, beyond_, cell_of_.data(), index_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("cell_key_kernel");
  sort_by_cell();
}

template <class Real>
void PairListBuilder<Real>::bin_periodic(const PeriodicFinder<Real>& find) {
  periodic_grid_kernel<Real><<<1, 1, 0, stream_>>>(bounds_.data(), static_cast<double>(cell_),
                                                   sheared_slack_, max_cells(n_), find.ps.frame,
                                                   periodic_grid_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("periodic_grid_kernel");
  periodic_cell_key_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(
      find.c, find.ps, beyond_, cell_of_.data(), index_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("periodic_cell_key_kernel");
  sort_by_cell();
}

template <class Real>
void PairListBuilder<Real>::sort_by_cell() {
  std::size_t bytes = temp_.size();
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp_.data(), bytes, cell_of_.data(),
                                                    sorted_cell_.data(), index_.data(),
                                                    sorted_.data(), n_, 0, cell_bits_, stream_));
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(cell_start_.data(), 0, cell_start_.bytes(), stream_));
  TRIDEM_CUDA_CHECK(cudaMemsetAsync(cell_end_.data(), 0, cell_end_.bytes(), stream_));
  cell_range_kernel<<<blocks(n_), kBlock, 0, stream_>>>(sorted_cell_.data(), n_, beyond_,
                                                        cell_start_.data(), cell_end_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("cell_range_kernel");
}

template <class Real>
template <class Finder>
void PairListBuilder<Real>::fill_rows(const Finder& find) {
  count_rows_kernel<<<blocks(n_), kBlock, 0, stream_>>>(find, n_, row_count_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("count_rows_kernel");
  size_rows();
  fill_rows_kernel<Real><<<blocks(n_), kBlock, 0, stream_>>>(find, n_, history());
  TRIDEM_CUDA_CHECK_LAUNCH("fill_rows_kernel");
}

template <class Real>
void PairListBuilder<Real>::size_rows() {
  offset_.swap(old_offset_);
  // The old list into phases_ (its details are not needed while a list is built), so that
  // the new one is written where the steps read it.
  old_count_ = count_;
  if (count_ > 0) {
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(phases_.old_partner(), partner_.data(),
                                      static_cast<std::size_t>(count_) * sizeof(int),
                                      cudaMemcpyDeviceToDevice, stream_));
    TRIDEM_CUDA_CHECK(
        cudaMemcpyAsync(phases_.old_slip(), slip_.data(),
                        static_cast<std::size_t>(count_) * sizeof(physics::PairSlip<Real>),
                        cudaMemcpyDeviceToDevice, stream_));
  }
  std::size_t bytes = temp_.size();
  TRIDEM_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.data(), bytes, row_count_.data(),
                                                  offset_.data(), n_ + 1, stream_));
  TRIDEM_CUDA_CHECK(cudaMemcpyAsync(total_.data(), offset_.data() + n_, sizeof(int),
                                    cudaMemcpyDeviceToHost, stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  count_ = *total_.data();
  if (count_ < 0) throw RunError("the pair list overflowed 2^31 pairs: too many particles for one GPU");
  // Denser than reserved: grow with headroom (the only allocation a running loop makes).
  if (static_cast<std::size_t>(count_) > partner_.size())
    reserve_pairs(pair_slots_for(static_cast<std::size_t>(count_)));
  old_count_ = 0;
}

template <class Real>
RowHistory<Real> PairListBuilder<Real>::history() const {
  return {offset_.data(), partner_.data(),    emitter_.data(),       phases_.slot_id(),
          slip_.data(),   old_offset_.data(), phases_.old_partner(), phases_.old_slip()};
}

template <class Real>
void PairListBuilder<Real>::index_rows() {
  std::size_t bytes = phases_.sort_temp_bytes();
  TRIDEM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(
      phases_.sort_temp(), bytes, partner_.data(), phases_.sorted_partner(), phases_.slot_id(),
      reverse_slot_.data(), count_, 0, particle_bits_, stream_));
  range_start_kernel<<<blocks(n_ + 1), kBlock, 0, stream_>>>(phases_.sorted_partner(), count_, n_,
                                                             reverse_offset_.data());
  TRIDEM_CUDA_CHECK_LAUNCH("range_start_kernel (reverse index)");
  // A pair too deep writes its detail on any step, and a blow-up's report looks for it in
  // its emitter's row: the other slots must not hold the build's scratch.
  phases_.clear_details(static_cast<std::size_t>(count_), stream_);
}

template <class Real>
void PairListBuilder<Real>::load(const std::vector<int>& offset, const std::vector<int>& partner,
                                 const std::vector<physics::PairSlip<Real>>& slip) {
  if (partner.size() > partner_.size() || slip.size() > partner_.size()) {
    reserve_pairs(pair_slots_for(partner.size()));
    clear_details();
  }
  auto copy = [this](auto& buffer, const auto& host) {
    if (!host.empty())
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(buffer.data(), host.data(),
                                        host.size() * sizeof(host[0]),
                                        cudaMemcpyHostToDevice, stream_));
  };
  copy(offset_, offset);
  copy(partner_, partner);
  copy(slip_, slip);
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  count_ = static_cast<int>(partner.size());
}

template <class Real>
PairArrays<Real> PairListBuilder<Real>::arrays() const {
  return {count_,       offset_.data(),   partner_.data(),        emitter_.data(),     slip_.data(),
          load_.data(), phases_.detail(), reverse_offset_.data(), reverse_slot_.data()};
}

template <class Real>
void PairListBuilder<Real>::download(std::vector<int>& offset, std::vector<int>& partner,
                                     std::vector<physics::PairSlip<Real>>* slip,
                                     std::vector<physics::PairForce<Real>>* result) const {
  const auto count = static_cast<std::size_t>(count_);
  offset.resize(static_cast<std::size_t>(n_) + 1);
  partner.resize(count);
  auto copy = [this](auto& host, const auto& buffer) {
    if (!host.empty())
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host.data(), buffer.data(),
                                        host.size() * sizeof(host[0]),
                                        cudaMemcpyDeviceToHost, stream_));
  };
  copy(offset, offset_);
  copy(partner, partner_);
  if (slip) {
    slip->resize(count);
    copy(*slip, slip_);
  }
  std::vector<physics::PairLoad<Real>> load(result ? count : 0);
  std::vector<physics::PairDetail<Real>> detail(result ? count : 0);
  copy(load, load_);
  if (!detail.empty())
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(detail.data(), phases_.detail(),
                                      detail.size() * sizeof(detail[0]), cudaMemcpyDeviceToHost,
                                      stream_));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  if (result) {
    result->resize(count);
    for (std::size_t s = 0; s < count; ++s) (*result)[s] = physics::joined(load[s], detail[s]);
  }
}

template <class Real>
void PairListBuilder<Real>::clear_details() const {
  phases_.clear_details(phases_.slots(), stream_);
}

template class PairListBuilder<float>;
template class PairListBuilder<double>;

}  // namespace tridem::cuda
