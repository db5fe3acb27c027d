#pragma once
// A typed block of GPU memory owned by one object: allocated at start (the time loop never
// allocates), freed when the owner goes, copied to and from host vectors with checks.
#include "backends/cuda/cuda_check.cuh"

#include <cstddef>
#include <utility>
#include <vector>

namespace tridem::cuda {

template <class T>
class DeviceBuffer {
 public:
  using value_type = T;
  DeviceBuffer() = default;
  explicit DeviceBuffer(std::size_t n) { allocate(n); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& o) noexcept { swap(o); }
  DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
    swap(o);
    return *this;
  }
  ~DeviceBuffer() {
    if (data_) cudaFree(data_);
  }

  /// Replaces the contents with n uninitialised elements.
  void allocate(std::size_t n) {
    DeviceBuffer fresh;
    if (n > 0) TRIDEM_CUDA_CHECK(cudaMalloc(reinterpret_cast<void**>(&fresh.data_), n * sizeof(T)));
    fresh.size_ = n;
    swap(fresh);
  }
  void upload(const std::vector<T>& host) {
    if (size_ < host.size()) allocate(host.size());
    if (host.empty()) return;
    TRIDEM_CUDA_CHECK(cudaMemcpy(data_, host.data(), host.size() * sizeof(T),
                                 cudaMemcpyHostToDevice));
    // From pageable memory cudaMemcpy may return before the DMA lands, and the solver's
    // stream does not wait for the legacy stream: wait here, so kernels see the data.
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(cudaStreamLegacy));
  }
  /// The first `host.size()` elements (synchronous: only checkpoints and errors use it).
  void download(std::vector<T>& host) const {
    if (!host.empty())
      TRIDEM_CUDA_CHECK(cudaMemcpy(host.data(), data_, host.size() * sizeof(T),
                                   cudaMemcpyDeviceToHost));
  }
  void swap(DeviceBuffer& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
  }

  T* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return size_ * sizeof(T); }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

/// GPU memory for a while of one stream's work (a frame's scratch): allocated and freed in
/// the stream's order from CUDA's pool (cudaMallocAsync), so that neither waits for the
/// device, and kept only while the work that uses it is queued, not for the whole run.
template <class T>
class StreamBuffer {
 public:
  StreamBuffer(std::size_t n, cudaStream_t stream) : size_(n), stream_(stream) {
    if (n > 0)
      TRIDEM_CUDA_CHECK(cudaMallocAsync(reinterpret_cast<void**>(&data_), n * sizeof(T), stream));
  }
  StreamBuffer(const StreamBuffer&) = delete;
  StreamBuffer& operator=(const StreamBuffer&) = delete;
  /// Freed after the work queued on the stream so far.
  ~StreamBuffer() {
    if (data_) cudaFreeAsync(data_, stream_);
  }
  T* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return size_ * sizeof(T); }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
  cudaStream_t stream_;
};

/// Page-locked host memory: device-to-host copies into it run at full bus speed.
template <class T>
class PinnedBuffer {
 public:
  PinnedBuffer() = default;
  PinnedBuffer(const PinnedBuffer&) = delete;
  PinnedBuffer& operator=(const PinnedBuffer&) = delete;
  ~PinnedBuffer() {
    if (data_) cudaFreeHost(data_);
  }
  void allocate(std::size_t n) {
    if (data_) cudaFreeHost(data_);
    data_ = nullptr;
    size_ = 0;
    if (n > 0) TRIDEM_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&data_), n * sizeof(T)));
    size_ = n;
  }
  T* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace tridem::cuda
