#pragma once
// Writers index every per-particle array by particle; a snapshot filled inconsistently by
// a solver would otherwise read out of bounds. Checking once per file is cheap.
#include "tridem/snapshot.hpp"

#include <string_view>

namespace tridem::io {

/// Throws Error unless every per-particle array has size() entries.
void check_snapshot(const Snapshot&, std::string_view writing);

/// Throws Error unless the body columns are consistent: all empty (every triangle its own
/// body), or member_body of size() entries, body_first of body_count() + 1 offsets from 0
/// to size(), ascending, each triangle inside its body's range, and every other body
/// column of body_count() entries (or, with `members_only`, every other one empty: a
/// frame read back knows which body each triangle is in, and no more).
void check_bodies(const Snapshot&, std::string_view writing, bool members_only = false);

/// Throws Error unless every contact names two existing particles and, in float precision
/// (contact_precision), its force, normal and depth are float32s.
void check_contacts(const Snapshot&, std::string_view writing);

}  // namespace tridem::io
