#include "io/output/frame_thread.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

namespace tridem::io {

FrameThread::FrameThread(Write write) : write_(std::move(write)), thread_([this] { run(); }) {}

FrameThread::~FrameThread() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !busy_; });
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FrameThread::wait_idle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [this] { return !busy_; });
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void FrameThread::submit(Snapshot& s, ContactCopy* contacts) {
  {
    std::unique_lock lock(mutex_);
    wait_idle(lock);
    std::swap(pending_, s);
    pending_contacts_ = contacts;
    busy_ = true;
  }
  changed_.notify_all();
}

void FrameThread::wait() {
  std::unique_lock lock(mutex_);
  wait_idle(lock);
}

void FrameThread::run() {
  // Below the stepping thread: a frame's writers (their OpenMP teams, made by this thread
  // and by the threads it starts, inherit its priority) take every core, and a stepping
  // thread that waits for one leaves the GPU idle between launches (issue 12: with the
  // contacts CSV the steps ran 15 % slower beside the writers). Where the system refuses,
  // the thread keeps its priority.
  const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), std::min(nice + kNicer, 19));
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return busy_ || stopping_; });
    if (!busy_) return;  // stopping, nothing in flight
    lock.unlock();
    std::exception_ptr failure;
    try {
      if (pending_contacts_) std::exchange(pending_contacts_, nullptr)->finish(pending_);
      write_(pending_);
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    failure_ = failure;
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace tridem::io
