#include "live/frame_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <limits>

namespace tridem::live {

namespace {

static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559);

/// Appends the bytes of trivially copyable values (the machines tridem runs on are
/// little-endian, as the page's typed arrays read them).
template <class T>
void put(std::string& out, const T& value) {
  const auto* bytes = reinterpret_cast<const char*>(&value);
  out.append(bytes, sizeof(T));
}

template <class T>
void put_array(std::string& out, const std::vector<T>& values) {
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// A finite float, so that a blown-up value cannot poison the page's ranges.
float finite(double v) { return std::isfinite(v) ? static_cast<float>(v) : 0.0F; }

}  // namespace

void fill_frame(const Snapshot& s, const EnergyRow& energy, FrameData& out) {
  const std::size_t n = s.size();
  out.step = s.step;
  out.time = s.time;
  const bool bonds = !s.bond_damage.empty();
  out.fields.resize(bonds ? 3 : 2);
  for (auto* v : {&out.x, &out.y, &out.angle}) v->resize(n);
  for (auto& f : out.fields) f.resize(n);
  out.wall_fx = out.wall_fy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out.x[i] = finite(s.x[i]);
    out.y[i] = finite(s.y[i]);
    out.angle[i] = finite(s.theta[i]);
    out.fields[0][i] = finite(std::hypot(s.vx[i], s.vy[i]));
    out.fields[1][i] = finite(std::hypot(s.fx[i], s.fy[i]));
    if (s.motion[i] != Motion::Free) {
      out.wall_fx += s.fx[i];
      out.wall_fy += s.fy[i];
    }
  }
  if (bonds) {
    std::vector<float>& damage = out.fields[2];
    std::fill(damage.begin(), damage.end(), 0.0F);
    for (std::size_t b = 0; b < s.bond_damage.size(); ++b) {
      const float d = finite(s.bond_damage[b]);
      for (std::int32_t t : {s.bond_a[b], s.bond_b[b]})
        if (t >= 0 && static_cast<std::size_t>(t) < n)
          damage[static_cast<std::size_t>(t)] = std::max(damage[static_cast<std::size_t>(t)], d);
    }
  }
  // The colour ranges over the free triangles: walls' loads would swamp the grains'.
  out.ranges.assign(2 * out.fields.size(), 0.0F);
  for (std::size_t k = 0; k < out.fields.size(); ++k) {
    float lo = std::numeric_limits<float>::max();
    float hi = std::numeric_limits<float>::lowest();
    for (std::size_t i = 0; i < n; ++i)
      if (s.motion[i] == Motion::Free) {
        lo = std::min(lo, out.fields[k][i]);
        hi = std::max(hi, out.fields[k][i]);
      }
    if (lo <= hi) {
      out.ranges[2 * k] = lo;
      out.ranges[2 * k + 1] = hi;
    }
  }
  out.kinetic = energy.kinetic;
  out.potential = energy.potential;
  out.elastic = energy.budget.elastic;
  out.dissipated = energy.budget.dissipated_damping + energy.budget.dissipated_friction +
                   energy.budget.dissipated_local + energy.budget.dissipated_fracture;
  out.wall_work = energy.budget.wall_work;
}

std::string encode_frame(const FrameData& f) {
  const std::size_t n = f.size();
  const auto fields = static_cast<std::uint32_t>(f.fields.size());
  std::string out;
  out.reserve(32 + 8 * fields + 4 * n * (3 + fields));
  put(out, kFrameMessage);
  put(out, static_cast<std::uint32_t>(n));
  put(out, fields);
  put(out, std::uint32_t{0});
  put(out, f.time);
  put(out, f.step);
  for (std::size_t k = 0; k < 2 * fields; ++k) put(out, k < f.ranges.size() ? f.ranges[k] : 0.0F);
  put_array(out, f.x);
  put_array(out, f.y);
  put_array(out, f.angle);
  for (const auto& field : f.fields) put_array(out, field);
  return out;
}

std::string encode_geometry(const Snapshot& s) {
  const std::size_t n = s.size();
  std::string out;
  out.reserve(16 + 36 * n);
  put(out, kGeometryMessage);
  put(out, static_cast<std::uint32_t>(n));
  put(out, (s.member_body.empty() ? 0U : kHasBodies) | (s.bond_damage.empty() ? 0U : kHasBonds));
  put(out, std::uint32_t{0});
  for (std::size_t i = 0; i < n; ++i) {
    const double c = std::cos(s.theta[i]);
    const double sn = std::sin(s.theta[i]);
    const double vx[3] = {s.x1[i], s.x2[i], s.x3[i]};
    const double vy[3] = {s.y1[i], s.y2[i], s.y3[i]};
    for (int k = 0; k < 3; ++k) {
      // The offset from the centroid turned by −θ: the triangle at angle 0.
      const double dx = vx[k] - s.x[i];
      const double dy = vy[k] - s.y[i];
      put(out, finite(c * dx + sn * dy));
      put(out, finite(-sn * dx + c * dy));
    }
  }
  for (std::size_t i = 0; i < n; ++i) put(out, static_cast<std::uint32_t>(s.material[i]));
  for (std::size_t i = 0; i < n; ++i) put(out, static_cast<std::uint32_t>(s.body_of(i)));
  for (std::size_t i = 0; i < n; ++i) put(out, static_cast<std::uint32_t>(s.motion[i]));
  return out;
}

std::string encode_stats(const FrameData& f, bool paused, int fps) {
  // Non-finite numbers are not JSON: a blown-up budget shows as null.
  const auto num = [](double v) {
    return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string("null");
  };
  return fmt::format(
      R"({{"step":{},"time":{},"kinetic":{},"potential":{},"elastic":{},"dissipated":{},)"
      R"("wall_work":{},"wall_fx":{},"wall_fy":{},"paused":{},"fps":{}}})",
      f.step, num(f.time), num(f.kinetic), num(f.potential), num(f.elastic), num(f.dissipated),
      num(f.wall_work), num(f.wall_fx), num(f.wall_fy), paused ? "true" : "false", fps);
}

}  // namespace tridem::live
