#pragma once
// How a pair's contact history reaches the next step, on every backend: the new row of an
// emitter is walked once beside its old row (both sorted by partner), and each pair takes
// the history its old slot holds, or none if it is new. The CPU carries it while computing
// the pair forces, the GPU when it builds the rows; the walk is this one.
#include "tridem/hd.hpp"

#include <cstdint>

namespace tridem {

/// An emitter's old row, walked forward as its new row asks for partners in ascending order.
template <class Index, class Slip>
struct OldRow {
  const std::int32_t* partner;
  const Slip* slip;
  Index at;   ///< the row's first slot, then the first not yet passed
  Index end;  ///< one past the row's last slot

  /// The history of the pair with partner j (j no lower than the last asked), or a
  /// zero history for a pair that was not in the old row.
  TRIDEM_HD Slip history_of(std::int32_t j) {
    while (at < end && partner[at] < j) ++at;
    return at < end && partner[at] == j ? slip[at] : Slip{};
  }
};

}  // namespace tridem
