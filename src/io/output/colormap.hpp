#pragma once
// Colours for the renderer: a perceptually uniform sequential map for speeds and a
// categorical palette for materials, neither of which contains the walls' grey.
namespace tridem::io {

struct Rgb {
  double r, g, b;  ///< each in [0, 1]
};

/// A viridis-like map: dark blue-purple at 0 through teal to yellow at 1; t is clamped.
Rgb sequential_color(double t);

/// Distinct colours for material indices, repeating after a dozen.
Rgb categorical_color(int index);

inline constexpr Rgb kWallGrey{0.62, 0.62, 0.62};

}  // namespace tridem::io
