#pragma once
// What a StateCopy (tridem/state_copy.hpp) writes into a Snapshot, for its implementations.
#include "tridem/snapshot.hpp"

#include <cstddef>

namespace tridem {

/// The fields a StateCopy fills: the shown fields for n particles and bonds' damage.
void resize_copied_fields(Snapshot& s, std::size_t n, std::size_t bonds);
/// Those fields, step and time of `from` into `to`, without copying the arrays.
void hand_over_copied_fields(Snapshot& from, Snapshot& to);

}  // namespace tridem
