#pragma once
// The tridem program's OpenMP threads wait passively (issue 12): a thread that reaches a
// barrier early sleeps instead of spinning. libgomp's default spins some 300 000 times
// first (milliseconds), and when other programs share the cores that spinning takes the
// core from the very thread it waits for: on 2 busy cores the bundled example's OpenMP
// steps took 24-40 times the serial solver's with the default, 0.5-1.5 times with
// OMP_WAIT_POLICY=passive (medians; docs/performance.md, "OpenMP on shared cores").
//
// The runtime reads its settings once, as it is loaded, before main() (a setting made in
// main() is too late, and one made by an ELF pre-initialiser is undone by the C library's
// own start-up): so the program starts itself again, once, with OMP_WAIT_POLICY=passive in
// its environment. A user's own OMP_WAIT_POLICY or GOMP_SPINCOUNT is left as it is, as is
// an MPI rank's environment. A program linking the library (make_solver) keeps the
// runtime's default.

namespace tridem::app {

/// Call first in main(): returns when nothing is to change or the restart failed.
void wait_passively_unless_told(char** argv);

}  // namespace tridem::app
