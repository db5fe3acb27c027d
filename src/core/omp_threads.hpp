#pragma once
// The OpenMP thread count of one solver, set for the time it runs and restored after: a
// program with two solvers, or its own parallel code beside one, keeps its own setting.
#include <omp.h>

namespace tridem {

class ScopedOmpThreads {
 public:
  /// `threads` = 0 leaves the runtime's setting alone.
  explicit ScopedOmpThreads(int threads) : saved_(omp_get_max_threads()), set_(threads > 0) {
    if (set_) omp_set_num_threads(threads);
  }
  ~ScopedOmpThreads() {
    if (set_) omp_set_num_threads(saved_);
  }
  ScopedOmpThreads(const ScopedOmpThreads&) = delete;
  ScopedOmpThreads& operator=(const ScopedOmpThreads&) = delete;

 private:
  int saved_;
  bool set_;
};

}  // namespace tridem
