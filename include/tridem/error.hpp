#pragma once
// Errors a user can act on. Every refusal of bad input or failed run is one of these,
// carrying a complete message; the app prints it and exits non-zero.
#include <stdexcept>
#include <string>

namespace tridem {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The scene file (or a scene built in code) is invalid.
struct SceneError : Error {
  using Error::Error;
};

/// The run cannot go on: unstable time step, blow-up, I/O failure.
struct RunError : Error {
  using Error::Error;
};

}  // namespace tridem
