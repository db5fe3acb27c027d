#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/render.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <memory>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct Pixel {
  int r, g, b;
  bool operator==(const Pixel&) const = default;
};

/// A PNG read back with cairo.
class Png {
 public:
  explicit Png(const std::filesystem::path& file)
      : surface_(cairo_image_surface_create_from_png(file.c_str()), cairo_surface_destroy) {
    if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot read " + file.string());
  }
  int width() const { return cairo_image_surface_get_width(surface_.get()); }
  int height() const { return cairo_image_surface_get_height(surface_.get()); }
  Pixel at(int x, int y) const {
    const unsigned char* row = cairo_image_surface_get_data(surface_.get()) +
                               static_cast<std::ptrdiff_t>(y) *
                                   cairo_image_surface_get_stride(surface_.get());
    std::uint32_t argb;  // native-endian 0xAARRGGBB
    std::memcpy(&argb, row + 4 * x, sizeof argb);
    return {int(argb >> 16 & 255), int(argb >> 8 & 255), int(argb & 255)};
  }

 private:
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
};

/// The pixel under world point (x, y) when the image is the sample's bounding box
/// [-1, 3] × [-1, 1] with no margin and no colour bar (a couple of pixels of slack).
Pixel pixel_at(const Png& png, double x, double y) {
  const int px = static_cast<int>((x + 1) / 4 * png.width());
  const int py = static_cast<int>((1 - y) / 2 * png.height());
  return png.at(px, py);
}

RenderOptions tight(RenderOptions::ColorBy by) {
  RenderOptions o;
  o.width = 400;
  o.margin = 0;
  o.colorbar = false;
  o.color_by = by;
  return o;
}

constexpr Pixel kWhite{255, 255, 255};

bool is_grey(Pixel p) { return p.r == p.g && p.g == p.b && p.r > 60 && p.r < 220; }

TEST(Render, PngHasTheRequestedSize) {
  test::TempDir tmp;
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  render_png(test::sample_snapshot(), tmp.path() / "a.png", o);
  const Png png(tmp.path() / "a.png");
  EXPECT_EQ(png.width(), 320);
  EXPECT_EQ(png.height(), 240);
  EXPECT_EQ(png.at(0, 0), kWhite);
}

TEST(Render, ZeroHeightKeepsTheAspect) {
  test::TempDir tmp;
  render_png(test::sample_snapshot(), tmp.path() / "a.png",
             tight(RenderOptions::ColorBy::Speed));
  const Png png(tmp.path() / "a.png");
  EXPECT_EQ(png.width(), 400);
  EXPECT_NEAR(png.height(), 200, 4);  // the sample is twice as wide as high
}

TEST(Render, FreeTrianglesColouredByTheirSpeedAndWallsGrey) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  render_png(s, tmp.path() / "a.png", tight(RenderOptions::ColorBy::Speed));
  const Png png(tmp.path() / "a.png");
  const Pixel slow = pixel_at(png, s.x[0], s.y[0]);
  const Pixel fast = pixel_at(png, s.x[1], s.y[1]);
  const Pixel wall = pixel_at(png, s.x[2], s.y[2]);
  EXPECT_NE(slow, kWhite);
  EXPECT_NE(fast, kWhite);
  EXPECT_FALSE(is_grey(slow));
  EXPECT_FALSE(is_grey(fast));
  // Viridis runs from dark to bright: the faster particle is the lighter one.
  EXPECT_GT(fast.r + fast.g + fast.b, slow.r + slow.g + slow.b);
  EXPECT_TRUE(is_grey(wall)) << wall.r << "," << wall.g << "," << wall.b;
  // Far from every triangle: background.
  EXPECT_EQ(pixel_at(png, -0.9, 0.9), kWhite);
}

TEST(Render, ColourByMaterialUsesDistinctColours) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.vx = s.vy = {0, 0, 0};  // speed plays no part
  render_png(s, tmp.path() / "a.png", tight(RenderOptions::ColorBy::Material));
  const Png png(tmp.path() / "a.png");
  const Pixel a = pixel_at(png, s.x[0], s.y[0]);
  const Pixel b = pixel_at(png, s.x[1], s.y[1]);
  EXPECT_NE(a, b);
  EXPECT_NE(a, kWhite);
  EXPECT_FALSE(is_grey(a));
  EXPECT_FALSE(is_grey(b));
  EXPECT_TRUE(is_grey(pixel_at(png, s.x[2], s.y[2])));
}

TEST(Render, ColourBarAddsLabelsBesideTheParticles) {
  test::TempDir tmp;
  RenderOptions o;
  o.width = 600;
  render_png(test::sample_snapshot(), tmp.path() / "a.png", o);
  const Png png(tmp.path() / "a.png");
  // Some non-white pixel in the right-hand strip reserved for the bar.
  bool drawn = false;
  for (int y = 0; y < png.height() && !drawn; ++y)
    for (int x = png.width() - 60; x < png.width() && !drawn; ++x)
      drawn = !(png.at(x, y) == kWhite);
  EXPECT_TRUE(drawn);
}

// Cracks (docs/fracture.md): a broken bond's edge is drawn red over the triangles, an
// intact one not at all.
TEST(Render, BrokenBondsAreDrawnRed) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  render_png(s, tmp.path() / "plain.png", tight(RenderOptions::ColorBy::Speed));
  s.bond_a = {0, 0};
  s.bond_b = {1, 1};
  s.bond_damage = {1.0, 0.0};
  s.bond_broken = {1, 0};
  s.bond_x0 = {s.x[0] - 0.1, s.x[1] - 0.1};
  s.bond_y0 = {s.y[0], s.y[1]};
  s.bond_x1 = {s.x[0] + 0.1, s.x[1] + 0.1};
  s.bond_y1 = {s.y[0], s.y[1]};
  render_png(s, tmp.path() / "cracked.png", tight(RenderOptions::ColorBy::Speed));
  const Png plain(tmp.path() / "plain.png"), cracked(tmp.path() / "cracked.png");
  const Pixel crack = pixel_at(cracked, s.x[0], s.y[0]);
  EXPECT_GT(crack.r, 180);
  EXPECT_LT(crack.g, 60);
  EXPECT_LT(crack.b, 60);
  EXPECT_EQ(pixel_at(cracked, s.x[1], s.y[1]), pixel_at(plain, s.x[1], s.y[1]))
      << "an intact bond is not drawn";
}

TEST(Render, BadOptionsAndUnwritableFileThrow) {
  test::TempDir tmp;
  RenderOptions o;
  o.width = 0;
  EXPECT_THROW(render_png(test::sample_snapshot(), tmp.path() / "a.png", o), Error);
  EXPECT_THROW(render_png(test::sample_snapshot(), tmp.path() / "missing" / "a.png", {}), Error);
}

TEST(Render, EmptySnapshotGivesABlankImage) {
  test::TempDir tmp;
  render_png(Snapshot{}, tmp.path() / "a.png", {});
  const Png png(tmp.path() / "a.png");
  EXPECT_EQ(png.width(), 1200);
  EXPECT_EQ(png.at(png.width() / 2, png.height() / 2), kWhite);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
