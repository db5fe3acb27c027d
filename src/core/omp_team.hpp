#pragma once
// One OpenMP team for a whole step (issue 12). A parallel region per loop forks and joins
// the threads a dozen times a step; when other programs share the cores, every join waits
// for a thread the system has descheduled. Code written for a team runs its loops as
// worksharing loops (`#pragma omp for`) and its serial parts in team_single, and is entered
// through on_team: inside a team it runs on that team's threads (no region of its own), and
// outside one it makes one region for the call. The same code then serves a step that is one
// region, a caller that wants one function in parallel, and the serial solver (a team of one).
// A step still has about 18 barriers; how a thread waits at them matters more than their
// number: with the runtime's default spinning the OpenMP step collapses on busy cores,
// region or not, and with passive waiting it does not (docs/performance.md, "OpenMP on
// shared cores"; the tridem program waits passively: app/startup_environment.hpp).
#include <exception>
#include <omp.h>

namespace tridem {

namespace detail {
/// Whether this thread runs inside a team made by on_team (set on every thread of it). A
/// region of someone else's, or a region on_team did not make, does not count: code
/// called there makes its own.
inline thread_local bool in_team = false;
/// The team's slot for an exception of its first thread's serial parts (team_master).
inline thread_local std::exception_ptr* master_error = nullptr;
}  // namespace detail

/// Runs body() as team code: on the caller's team when called from inside on_team (every
/// thread of the team must call it), else on a region of its own, of the runtime's threads
/// when `parallel` and of the calling thread alone otherwise. An exception of body() must
/// reach every thread at the same point (team_single does that); it is rethrown here, once.
template <class Body>
void on_team(bool parallel, Body&& body) {
  if (detail::in_team) return body();
  std::exception_ptr error, master_error;
#pragma omp parallel if (parallel)
  {
    detail::in_team = true;
    detail::master_error = &master_error;
    try {
      body();
    } catch (...) {
#pragma omp critical(tridem_team_error)
      if (!error) error = std::current_exception();
    }
    detail::in_team = false;
    detail::master_error = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

/// Team code: f() runs on one thread while the others wait for it (a `single` and its
/// barrier). An exception f() throws is rethrown on every thread, so that the whole team
/// leaves together and none is left waiting at a barrier.
template <class F>
void team_single(F&& f) {
  std::exception_ptr error;
#pragma omp single copyprivate(error)
  {
    try {
      f();
    } catch (...) {
      error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

/// Team code: f() runs on the team's first thread, the one that called on_team (MPI's
/// calls must come from the program's main thread), while the others wait for it; an
/// exception it throws is rethrown on every thread, as in team_single.
template <class F>
void team_master(F&& f) {
  if (!detail::in_team) return f();
  if (omp_get_thread_num() == 0) {
    try {
      f();
    } catch (...) {
      *detail::master_error = std::current_exception();
    }
  }
#pragma omp barrier
  if (*detail::master_error) std::rethrow_exception(*detail::master_error);
}

/// Team code: folds every thread's `mine` into `shared` (shared by the team, holding
/// fold's identity before) one thread at a time, then waits for the whole team, after
/// which every thread reads the same `shared`. For folds whose result does not depend on
/// the order (min, max): the team's result is then the serial one.
template <class T, class Fold>
void team_fold(T& shared, const T& mine, Fold fold) {
#pragma omp critical(tridem_team_fold)
  shared = fold(shared, mine);
#pragma omp barrier
}

}  // namespace tridem
