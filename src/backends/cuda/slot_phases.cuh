#pragma once
// The pair slots' memory that no two phases of the CUDA step use at once (issue 12: GPU
// memory a pair). While a list is built: the list it replaces (partners and slips, which
// the contact history is carried from), the new slots' ids and the reverse index's sort
// keys and CUB scratch. Between builds: the pair results' details (physics::PairDetail: the
// contact point, normal and depth, written on the last step of an advance and by a pair too
// deep, read by snapshots, energy() and a blow-up's report). One allocation, sized for the
// larger phase: a slot takes 28 bytes here in float (56 in double) where separate arrays
// took 56 (96); 68 of 96 bytes a slot in all in float, 124 of 160 in double.
//
//   byte 0          section b                section c
//   | slot ids     | old partners           | old slips              |   during a build,
//   | slot ids     | sorted partners        | CUB sort scratch       |   then (reverse index)
//   | details ...                                                    |   between builds
#include "backends/cuda/cuda_check.cuh"
#include "backends/cuda/device_buffer.cuh"
#include "physics/pair_record.hpp"

#include <algorithm>
#include <cstddef>

namespace tridem::cuda {

template <class Real>
class SlotPhases {
 public:
  /// Room for `slots` slots and `sort_temp` bytes of CUB's reverse-index sort. The first
  /// `keep` slots of the old list (a build growing the slots) move to the new layout;
  /// nothing else is kept. Waits for `stream` when it allocates.
  void reserve(std::size_t slots, std::size_t sort_temp, std::size_t keep, cudaStream_t stream) {
    const Layout next(slots, sort_temp);
    if (slots == slots_ && sort_temp <= sort_temp_) return;
    DeviceBuffer<unsigned char> fresh(next.bytes);
    if (keep > 0) {
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(fresh.data() + next.b, old_partner(), keep * sizeof(int),
                                        cudaMemcpyDeviceToDevice, stream));
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(fresh.data() + next.c, old_slip(),
                                        keep * sizeof(physics::PairSlip<Real>),
                                        cudaMemcpyDeviceToDevice, stream));
    }
    // The old allocation is freed at the swap: the copies from it must be done.
    TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
    memory_.swap(fresh);
    slots_ = slots;
    sort_temp_ = sort_temp;
    layout_ = next;
  }

  std::size_t slots() const { return slots_; }
  std::size_t bytes() const { return memory_.bytes(); }

  // A build: the history carry reads the old list and writes the slot ids ...
  int* slot_id() const { return at<int>(0); }
  int* old_partner() const { return at<int>(layout_.b); }
  physics::PairSlip<Real>* old_slip() const { return at<physics::PairSlip<Real>>(layout_.c); }
  // ... then the reverse index sorts the partners with the slot ids.
  int* sorted_partner() const { return at<int>(layout_.b); }
  unsigned char* sort_temp() const { return at<unsigned char>(layout_.c); }
  std::size_t sort_temp_bytes() const { return sort_temp_; }

  /// Between builds.
  physics::PairDetail<Real>* detail() const { return at<physics::PairDetail<Real>>(0); }
  /// Zeroes the first `count` slots' details (a build leaves its scratch there).
  void clear_details(std::size_t count, cudaStream_t stream) const {
    if (count > 0)
      TRIDEM_CUDA_CHECK(cudaMemsetAsync(
          memory_.data(), 0, std::min(count, slots_) * sizeof(physics::PairDetail<Real>), stream));
  }

 private:
  /// Byte offsets of sections b and c, and the whole size; each section 256-byte aligned.
  struct Layout {
    std::size_t b = 0, c = 0, bytes = 0;
    Layout() = default;
    Layout(std::size_t slots, std::size_t sort_temp)
        : b(aligned(slots * sizeof(int))),
          c(aligned(b + slots * sizeof(int))),
          bytes(std::max(slots * sizeof(physics::PairDetail<Real>),
                         c + std::max(slots * sizeof(physics::PairSlip<Real>), sort_temp))) {}
  };
  static std::size_t aligned(std::size_t bytes) { return (bytes + 255) / 256 * 256; }
  template <class T>
  T* at(std::size_t offset) const {
    return reinterpret_cast<T*>(memory_.data() + offset);
  }

  DeviceBuffer<unsigned char> memory_;
  std::size_t slots_ = 0, sort_temp_ = 0;
  Layout layout_;
};

}  // namespace tridem::cuda
