#pragma once
// A quick look at one state without ParaView: a PNG of the triangles, for reports, CI
// artefacts and movies assembled from frames.
#include "tridem/snapshot.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>

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
  /// Drawn in the top-left corner (a movie's time), when not empty.
  std::string label;
  /// The drawn region (lo x, lo y, hi x, hi y), m; unset: the frame's bounding box. A movie
  /// fixes it so that the picture does not jump between frames.
  std::optional<std::array<double, 4>> region;
};

/// Free triangles are coloured by speed |v| (viridis-like map), by material (categorical
/// palette) or by body (the palette again, neighbouring bodies in different colours);
/// fixed and prescribed ones are grey. A body of several triangles is drawn as one
/// polygon: the edges its members share are not outlined. y points up. Throws Error
/// on bad options or when cairo cannot draw or write the file.
void render_png(const Snapshot&, const std::filesystem::path& png, const RenderOptions& = {});

/// A frame (.vtu) read back for drawing with `options`: refuses (Error, naming the file and
/// what to draw instead) a frame written without its velocity when they colour by speed.
Snapshot read_frame_to_render(const std::filesystem::path& vtu, const RenderOptions& options);

/// Every frame of an output directory (frames/*.vtu, in step order) into one MP4 through
/// the `ffmpeg` program (Debian's ffmpeg), at `fps` frames per second: each frame labelled
/// with its time and step, drawn over the region of all frames, coloured by speed over one
/// range (that of all frames, unless `options` fixes it). Returns the number of frames.
/// Throws Error when there are no frames or ffmpeg is missing or fails.
std::size_t render_movie(const std::filesystem::path& dir, const std::filesystem::path& mp4,
                         const RenderOptions& options, int fps);

}  // namespace tridem
