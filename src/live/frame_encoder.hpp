#pragma once
// The live view's wire format (docs/live-view.md, "Wire format"): what a browser receives
// over the WebSocket. Binary messages, little-endian, every field 4-byte aligned so that
// the page reads them as typed arrays without copying:
//
//   geometry (once per client): u32 kind = 1, u32 n, u32 flags (1: bodies, 2: bonds),
//     u32 0; f32 local[6n] (each triangle's vertices about its centroid at angle 0);
//     u32 material[n]; u32 body[n]; u32 motion[n] (0 free, 1 fixed, 2 prescribed)
//   frame: u32 kind = 2, u32 n, u32 fields F, u32 0; f64 time; i64 step;
//     f32 range[2F] (min, max of each field over the free triangles); f32 x[n], y[n],
//     angle[n]; then f32 field[n] for each field: speed, contact force (|f|), and bond
//     damage (the largest of the triangle's bonds) when the scene has bonds
//
// and one text message (JSON) before each frame: the step's energy budget and wall forces.
// FrameData is what the stepping thread copies out of a Snapshot; the encoding runs on the
// server's thread.
#include "tridem/output.hpp"
#include "tridem/snapshot.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace tridem::live {

inline constexpr std::uint32_t kGeometryMessage = 1;
inline constexpr std::uint32_t kFrameMessage = 2;
inline constexpr std::uint32_t kHasBodies = 1;
inline constexpr std::uint32_t kHasBonds = 2;

/// One frame's poses and colour fields, in float, and the numbers of the plots.
struct FrameData {
  std::int64_t step = 0;
  double time = 0;
  std::vector<float> x, y, angle;
  std::vector<std::vector<float>> fields;  ///< speed, force[, damage]
  std::vector<float> ranges;               ///< min, max of each field over the free triangles
  double kinetic = 0, potential = 0, elastic = 0, dissipated = 0, wall_work = 0;
  double wall_fx = 0, wall_fy = 0;  ///< the contact force on the fixed and prescribed triangles
  std::size_t size() const { return x.size(); }
};

/// Fills `out` from a snapshot and its energy row, reusing out's storage (no allocation
/// once it has held a frame of this size).
void fill_frame(const Snapshot& snap, const EnergyRow& energy, FrameData& out);

std::string encode_frame(const FrameData& frame);
/// The run's triangles as the page draws them: vertices about the centroid, turned back
/// by the snapshot's angle, and the ids the colours by material and body need.
std::string encode_geometry(const Snapshot& snap);
/// The JSON text message of a frame (numbers only, no user text).
std::string encode_stats(const FrameData& frame, bool paused, int fps);

}  // namespace tridem::live
