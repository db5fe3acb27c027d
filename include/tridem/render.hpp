#pragma once
// A quick look at one state without ParaView: a PNG of the triangles, for reports, CI
// artefacts and movies assembled from frames.
#include "tridem/snapshot.hpp"

#include <filesystem>
#include <optional>

namespace tridem {

struct RenderOptions {
  int width = 1200;   ///< pixels
  int height = 0;     ///< pixels; 0 = follow the aspect of the particles' bounding box
  enum class ColorBy { Speed, Material, Body } color_by = ColorBy::Speed;
  /// Fixed ends of the speed colour scale, m/s. Unset: the frame's own min and max over
  /// free particles. Set both to keep colours comparable across the frames of a movie.
  std::optional<double> speed_min;
  std::optional<double> speed_max;
  bool colorbar = true;     ///< a min–max bar with labels when colouring by speed
  double margin = 0.03;     ///< blank border, as a fraction of the width
};

/// Free triangles are coloured by speed |v| (viridis-like map), by material (categorical
/// palette) or by body (the palette again, neighbouring bodies in different colours);
/// fixed and prescribed ones are grey. A body of several triangles is drawn as one
/// polygon: the edges its members share are not outlined. y points up. Throws Error
/// on bad options or when cairo cannot draw or write the file.
void render_png(const Snapshot&, const std::filesystem::path& png, const RenderOptions& = {});

}  // namespace tridem
