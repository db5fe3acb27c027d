#pragma once
// Writers index every per-particle array by particle; a snapshot filled inconsistently by
// a solver would otherwise read out of bounds. Checking once per file is cheap.
#include "tridem/snapshot.hpp"

#include <string_view>

namespace tridem::io {

/// Throws Error unless every per-particle array has size() entries.
void check_snapshot(const Snapshot&, std::string_view writing);

/// Throws Error unless every contact names two existing particles.
void check_contacts(const Snapshot&, std::string_view writing);

}  // namespace tridem::io
