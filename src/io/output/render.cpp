// PNG rendering with cairo. Coordinates are mapped to pixels by hand (no cairo transform)
// so that line widths and text sizes are in pixels whatever the domain's size.
#include "tridem/render.hpp"

#include "io/output/body_colors.hpp"
#include "io/output/body_outline.hpp"
#include "io/output/colormap.hpp"
#include "io/output/snapshot_check.hpp"
#include "tridem/error.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace tridem {
namespace {

constexpr int kMaxSide = 32767;  // cairo's image surface limit

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  void add(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  bool empty() const { return !(x0 <= x1); }
};

Box bounds(const Snapshot& s) {
  Box b;
  for (std::size_t k = 0; k < s.size(); ++k) {
    b.add(s.x1[k], s.y1[k]);
    b.add(s.x2[k], s.y2[k]);
    b.add(s.x3[k], s.y3[k]);
  }
  if (b.empty()) b = Box{0, 0, 1, 1};
  // A single flat or point-like extent still needs an area to fit into.
  const double pad = std::max({b.x1 - b.x0, b.y1 - b.y0, 1e-12}) * 0.5;
  if (b.x1 - b.x0 <= 0) b.x0 -= pad, b.x1 += pad;
  if (b.y1 - b.y0 <= 0) b.y0 -= pad, b.y1 += pad;
  return b;
}

struct CairoDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

void check(cairo_status_t status, const std::filesystem::path& png, std::string_view doing) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(fmt::format("cannot render '{}': cairo failed {}: {}", png.string(), doing,
                            cairo_status_to_string(status)));
}

void set_color(cairo_t* cr, io::Rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

struct Layout {
  int width = 0, height = 0;
  double scale = 1, ox = 0, oy = 0;
  double bar_width = 0;  ///< 0: no colour bar
  Box box;
  double px(double x) const { return ox + (x - box.x0) * scale; }
  double py(double y) const { return oy + (box.y1 - y) * scale; }  // y up
};

Layout layout(const Box& box, const RenderOptions& o, bool want_bar) {
  Layout l;
  l.box = box;
  l.width = o.width;
  const double w = o.width;
  double margin = std::min(std::max(2.0, o.margin * w), 0.25 * w);
  l.bar_width = want_bar ? std::clamp(0.12 * w, 60.0, 140.0) : 0;
  if (w - 2 * margin - l.bar_width < 0.5 * w) l.bar_width = 0;  // too narrow to be useful
  const double plot_w = w - 2 * margin - l.bar_width;
  const double bw = box.x1 - box.x0, bh = box.y1 - box.y0;
  if (o.height > 0) {
    l.height = o.height;
    margin = std::min(margin, 0.25 * o.height);
  } else {
    l.height = static_cast<int>(
        std::clamp(std::round(plot_w * bh / bw + 2 * margin), 1.0, double(kMaxSide)));
  }
  const double plot_h = std::max(1.0, l.height - 2 * margin);
  l.scale = std::min(plot_w / bw, plot_h / bh);
  l.ox = margin + 0.5 * (plot_w - bw * l.scale);
  l.oy = margin + 0.5 * (plot_h - bh * l.scale);
  return l;
}

/// The mean length of the triangles' first edges, m; 0 when none is finite.
double mean_edge(const Snapshot& s) {
  double sum = 0;
  std::size_t counted = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double e = std::hypot(s.x2[k] - s.x1[k], s.y2[k] - s.y1[k]);
    if (std::isfinite(e)) sum += e, ++counted;
  }
  return counted ? sum / static_cast<double>(counted) : 0;
}

/// Thin next to a triangle, but never thicker than a pixel: dense packings stay coloured.
double edge_width(const Snapshot& s, const Layout& l) {
  const double mean = s.size() > 0 && mean_edge(s) > 0 ? mean_edge(s) * l.scale : 10;
  return std::clamp(0.06 * mean, 0.15, 1.0);
}

constexpr int kPalette = 12;  // categorical_color's distinct colours

void draw_colorbar(cairo_t* cr, const Layout& l, double lo, double hi) {
  const double font = std::clamp(0.016 * l.width, 9.0, 16.0);
  const double x = l.width - l.bar_width;
  const double bar_w = 0.18 * l.bar_width;
  const double top = 0.2 * l.height + 1.5 * font, bottom = 0.8 * l.height;
  if (bottom - top < 2 * font) return;  // no room in a very flat image

  cairo_pattern_t* ramp = cairo_pattern_create_linear(0, bottom, 0, top);
  constexpr int kStops = 16;
  for (int k = 0; k <= kStops; ++k) {
    const double t = static_cast<double>(k) / kStops;
    const io::Rgb c = io::sequential_color(t);
    cairo_pattern_add_color_stop_rgb(ramp, t, c.r, c.g, c.b);
  }
  cairo_rectangle(cr, x, top, bar_w, bottom - top);
  cairo_set_source(cr, ramp);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(ramp);
  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);

  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font);
  const auto text = [&](double tx, double ty, const std::string& s) {
    cairo_move_to(cr, tx, ty);
    cairo_show_text(cr, s.c_str());
  };
  text(x, top - 0.6 * font, "|v| (m/s)");
  text(x + bar_w + 0.3 * font, top + 0.7 * font, fmt::format("{:.3g}", hi));
  text(x + bar_w + 0.3 * font, bottom, fmt::format("{:.3g}", lo));
}

/// The cracks of a bonded solid (docs/fracture.md): each broken bond's edge in red, each
/// damaged one in orange, more opaque the more damaged; intact bonds are not drawn.
void draw_bonds(cairo_t* cr, const Snapshot& s, const Layout& l) {
  const double width = std::clamp(3 * edge_width(s, l), 1.0, 3.0);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_width(cr, width);
  for (std::size_t k = 0; k < s.bond_a.size(); ++k) {
    const double d = s.bond_damage[k];
    if (!(d > 0) || !std::isfinite(s.bond_x0[k] + s.bond_y0[k] + s.bond_x1[k] + s.bond_y1[k]))
      continue;
    if (s.bond_broken[k])
      cairo_set_source_rgb(cr, 0.85, 0.05, 0.05);
    else
      cairo_set_source_rgba(cr, 1.0, 0.55, 0.0, 0.25 + 0.75 * std::min(d, 1.0));
    cairo_move_to(cr, l.px(s.bond_x0[k]), l.py(s.bond_y0[k]));
    cairo_line_to(cr, l.px(s.bond_x1[k]), l.py(s.bond_y1[k]));
    cairo_stroke(cr);
  }
}

}  // namespace

void render_png(const Snapshot& s, const std::filesystem::path& png, const RenderOptions& o) {
  // cairo would say only "error while writing to output stream".
  const std::filesystem::path folder = png.parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw Error(fmt::format("cannot render '{}': the folder '{}' does not exist", png.string(),
                            folder.string()));
  io::check_snapshot(s, png.string());
  io::check_bodies(s, png.string(), /*members_only=*/s.body_x.empty());
  if (o.width < 1 || o.width > kMaxSide || o.height < 0 || o.height > kMaxSide)
    throw Error(fmt::format("cannot render '{}': image size {}x{} is outside 1..{}",
                            png.string(), o.width, o.height, kMaxSide));
  if (!(o.margin >= 0 && o.margin < 0.5))
    throw Error(fmt::format("cannot render '{}': margin {} is outside [0, 0.5)", png.string(),
                            o.margin));

  const bool by_speed = o.color_by == RenderOptions::ColorBy::Speed;
  const bool by_body = o.color_by == RenderOptions::ColorBy::Body;
  // Bodies within a tenth of a mean edge of each other count as neighbours.
  const std::vector<int> body_color =
      by_body ? io::body_colors(s, 0.1 * mean_edge(s), kPalette) : std::vector<int>();
  // A body of several triangles is outlined as one polygon.
  const std::vector<std::uint8_t> inner = io::inner_edges(s);
  const bool outlines = !s.member_body.empty();
  std::vector<double> speed(s.size());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t k = 0; k < s.size(); ++k) {
    speed[k] = std::hypot(s.vx[k], s.vy[k]);
    if (s.motion[k] == Motion::Free && std::isfinite(speed[k])) {
      lo = std::min(lo, speed[k]);
      hi = std::max(hi, speed[k]);
    }
  }
  const bool any_free = lo <= hi;
  lo = o.speed_min.value_or(any_free ? lo : 0);
  hi = o.speed_max.value_or(any_free ? hi : 0);

  const Box region =
      o.region ? Box{(*o.region)[0], (*o.region)[1], (*o.region)[2], (*o.region)[3]} : bounds(s);
  if (region.empty() || !(region.x1 > region.x0 && region.y1 > region.y0))
    throw Error(fmt::format("cannot render '{}': the region to draw is empty", png.string()));
  const Layout l = layout(region, o, by_speed && o.colorbar && any_free);
  const std::unique_ptr<cairo_surface_t, CairoDeleter> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, l.width, l.height));
  check(cairo_surface_status(surface.get()), png, "to create the image");
  const std::unique_ptr<cairo_t, CairoDeleter> context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  check(cairo_status(cr), png, "to start drawing");

  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_line_width(cr, edge_width(s, l));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const auto finite = [&](std::size_t k) {
    return std::isfinite(s.x1[k] + s.y1[k] + s.x2[k] + s.y2[k] + s.x3[k] + s.y3[k]);
  };
  for (std::size_t k = 0; k < s.size(); ++k) {
    // A blown-up particle is left out rather than poisoning cairo's path.
    if (!finite(k)) continue;
    cairo_move_to(cr, l.px(s.x1[k]), l.py(s.y1[k]));
    cairo_line_to(cr, l.px(s.x2[k]), l.py(s.y2[k]));
    cairo_line_to(cr, l.px(s.x3[k]), l.py(s.y3[k]));
    cairo_close_path(cr);
    if (s.motion[k] != Motion::Free)
      set_color(cr, io::kWallGrey);
    else if (by_speed)
      set_color(cr, io::sequential_color(hi > lo ? (speed[k] - lo) / (hi - lo) : 0));
    else if (by_body)
      set_color(cr, io::categorical_color(body_color[static_cast<std::size_t>(s.body_of(k))]));
    else
      set_color(cr, io::categorical_color(s.material[k]));
    cairo_fill_preserve(cr);
    // With bodies, the fill's own colour covers the seams between members; the outlines
    // follow in a second pass, so that a neighbour's fill never hides them.
    if (!outlines) cairo_set_source_rgb(cr, 0.12, 0.12, 0.12);
    cairo_stroke(cr);
  }
  if (outlines) {
    cairo_set_source_rgb(cr, 0.12, 0.12, 0.12);
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (!finite(k)) continue;
      const double v[3][2] = {{s.x1[k], s.y1[k]}, {s.x2[k], s.y2[k]}, {s.x3[k], s.y3[k]}};
      for (int e = 0; e < 3; ++e) {
        if (inner[k] & (1u << e)) continue;
        cairo_move_to(cr, l.px(v[e][0]), l.py(v[e][1]));
        cairo_line_to(cr, l.px(v[(e + 1) % 3][0]), l.py(v[(e + 1) % 3][1]));
      }
    }
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_stroke(cr);
  }
  draw_bonds(cr, s, l);
  if (l.bar_width > 0) draw_colorbar(cr, l, lo, hi);
  if (!o.label.empty()) {
    const double font = std::clamp(0.022 * l.width, 10.0, 22.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, font);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, 0.5 * font, 1.4 * font);
    cairo_show_text(cr, o.label.c_str());
  }

  check(cairo_status(cr), png, "while drawing");
  cairo_surface_flush(surface.get());
  check(cairo_surface_write_to_png(surface.get(), png.c_str()), png, "to write the file");
}

}  // namespace tridem
