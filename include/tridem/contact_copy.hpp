#pragma once
// A frame's contact network copied beside the stepping (issue 12). On the GPU the network
// is most of a frame's snapshot (at 10^6 triangles in a dense pile some 6x10^6 contacts,
// 0.08 of a snapshot's 0.09 s): start() queues its compaction and download on the solver's
// stream and returns, the time loop hands the snapshot of the fields to the frame thread,
// and finish() there waits for the download and appends the contact records. The
// snapshot's fields (a few milliseconds) and the log rows stay on the stepping thread.
#include "tridem/snapshot.hpp"

#include <memory>

namespace tridem {

class Solver;

class ContactCopy {
 public:
  virtual ~ContactCopy() = default;
  /// Stepping thread, between two steps, after Solver::snapshot(s, false) of this step:
  /// starts copying the contacts of the last step. Not again before finish() has returned.
  virtual void start() = 0;
  /// Any thread, once after each start(), with that snapshot (its positions place each
  /// contact): appends the contacts, so that `s` is what Solver::snapshot(s, true) would
  /// have given, to the bit.
  virtual void finish(Snapshot& s) = 0;
};

/// The copy every backend can give: start() takes a whole snapshot with contacts on the
/// calling thread (synchronous), finish() appends its contacts. Not faster than taking
/// them with the snapshot; it runs the time loop's way of frames with copied contacts on
/// any backend (tests).
std::unique_ptr<ContactCopy> make_snapshot_contact_copy(const Solver& solver);

}  // namespace tridem
