#pragma once
// Frames written beside the stepping (issue 12): the time loop hands a snapshot it has
// already taken from the solver to this thread, which compresses and writes it while the
// solver steps on. At most one frame is in flight: handing over the next one waits for it.
// The snapshot changes hands by swap, so nothing is copied and, once two buffers have
// their size, nothing is allocated. A failure on the thread (disk full, permission) is
// kept and thrown on the caller's thread at the next hand-over or wait.
#include "tridem/contact_copy.hpp"
#include "tridem/snapshot.hpp"

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace tridem::io {

class FrameThread {
 public:
  using Write = std::function<void(const Snapshot&)>;
  explicit FrameThread(Write write);
  /// Waits for the frame in flight; its failure, if any, is dropped: an error already
  /// on its way out of the caller is the one to report.
  ~FrameThread();
  FrameThread(const FrameThread&) = delete;
  FrameThread& operator=(const FrameThread&) = delete;

  /// Waits for the previous frame (throwing its failure), then takes `s`'s contents and
  /// writes them; `s` gets the buffer of an earlier frame, which the next
  /// Solver::snapshot overwrites whole. With `contacts` (started at `s`'s step), the
  /// thread first appends the contacts it copies (ContactCopy::finish).
  void submit(Snapshot& s, ContactCopy* contacts = nullptr);
  /// Waits until no frame is in flight; throws the failure of the last one, if any.
  void wait();

  /// How much nicer (Linux's scheduling priority) the thread and its writers run than
  /// the thread that made it.
  static constexpr int kNicer = 5;

 private:
  void run();
  /// Under the lock: waits until idle, then throws a kept failure (once).
  void wait_idle(std::unique_lock<std::mutex>& lock);

  Write write_;
  std::mutex mutex_;
  std::condition_variable changed_;
  Snapshot pending_;
  ContactCopy* pending_contacts_ = nullptr;
  bool busy_ = false;
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::thread thread_;  ///< last: starts once the rest is ready
};

}  // namespace tridem::io
