// What the outputs show of bodies of several triangles: bodies.csv, final.csv's `body`
// column, the frames' `body` cell array (written and read back), `render --color body`,
// and the same on a run of a known scene.
#include "io/output/body_colors.hpp"
#include "io/output/body_outline.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/render.hpp"
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Two free square bodies of two triangles each, side by side ([0, 1]² and [1, 2] × [0, 1],
/// touching along x = 1), and a fixed lone triangle below them: bodies 0, 1 and 2,
/// triangles 0-1, 2-3 and 4. Values have long decimal expansions so that lost precision shows.
Snapshot bodies_snapshot() {
  Snapshot s;
  s.step = 300;
  s.time = 0.003;
  s.resize(5);
  const double v[5][6] = {{0, 0, 1, 0, 1, 1},
                          {0, 0, 1, 1, 0, 1},
                          {1, 0, 2, 0, 2, 1},
                          {1, 0, 2, 1, 1, 1},
                          {-1, -0.5, 3, -0.5, 1, -2}};
  for (std::size_t k = 0; k < 5; ++k) {
    s.x1[k] = v[k][0], s.y1[k] = v[k][1], s.x2[k] = v[k][2], s.y2[k] = v[k][3];
    s.x3[k] = v[k][4], s.y3[k] = v[k][5];
    s.x[k] = (v[k][0] + v[k][2] + v[k][4]) / 3;
    s.y[k] = (v[k][1] + v[k][3] + v[k][5]) / 3;
    s.vx[k] = k < 2 ? 0.1 : 0;
    s.omega[k] = k < 2 ? 1.0 / 3.0 : 0;
    s.mass[k] = k < 4 ? 1250 : 0;
    s.inertia[k] = k < 4 ? 104.16666666666667 : 0;
    s.motion[k] = k < 4 ? Motion::Free : Motion::Fixed;
  }
  s.resize_bodies(3);
  s.member_body = {0, 0, 1, 1, 2};
  s.body_first = {0, 2, 4, 5};
  s.body_x = {0.5, 1.5, 1};
  s.body_y = {0.5, 0.5, -1.0 / 3.0};
  s.body_theta = {0.25, -1.0 / 7.0, 0};
  s.body_vx = {0.1, 0, 0};
  s.body_vy = {-2.0 / 3.0, 1e-300, 0};
  s.body_omega = {1.0 / 3.0, 0, 0};
  s.body_fx = {1, -1, 0};
  s.body_mass = {2500, 2500, 0};
  s.body_inertia = {416.66666666666669, 416.66666666666669, 0};
  return s;
}

TEST(BodiesCsv, OneRowPerBodyFromTheBodyColumns) {
  test::TempDir tmp;
  const Snapshot s = bodies_snapshot();
  write_bodies_csv(tmp.path() / "bodies.csv", s);
  const auto lines = test::read_lines(tmp.path() / "bodies.csv");
  ASSERT_EQ(lines.size(), 1u + 3u);
  EXPECT_EQ(lines[0], "id,x,y,theta,vx,vy,omega,mass,inertia,members");
  const double members[3] = {2, 2, 1};
  for (std::size_t b = 0; b < 3; ++b) {
    const std::vector<double> expected = {
        double(b),    s.body_x[b],     s.body_y[b],    s.body_theta[b],   s.body_vx[b],
        s.body_vy[b], s.body_omega[b], s.body_mass[b], s.body_inertia[b], members[b]};
    EXPECT_EQ(test::numbers(lines[1 + b]), expected) << "body " << b;  // %.17g: exact
  }
}

TEST(BodiesCsv, WithoutBodiesEachTriangleIsABodyOfOneMember) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  write_bodies_csv(tmp.path() / "bodies.csv", s);
  const auto lines = test::read_lines(tmp.path() / "bodies.csv");
  ASSERT_EQ(lines.size(), 1 + s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::vector<double> expected = {double(k), s.x[k],     s.y[k],    s.theta[k],   s.vx[k],
                                          s.vy[k],   s.omega[k], s.mass[k], s.inertia[k], 1};
    EXPECT_EQ(test::numbers(lines[1 + k]), expected) << "triangle " << k;
  }
}

TEST(BodiesCsv, InconsistentBodiesAreRefused) {
  test::TempDir tmp;
  Snapshot s = bodies_snapshot();
  s.member_body[1] = 1;  // body 0's range holds a triangle of body 1
  EXPECT_THROW(write_bodies_csv(tmp.path() / "bodies.csv", s), Error);
  s = bodies_snapshot();
  s.body_mass.pop_back();
  EXPECT_THROW(write_bodies_csv(tmp.path() / "bodies.csv", s), Error);
  s = bodies_snapshot();
  s.body_first.back() = 4;  // the last triangle in no body
  EXPECT_THROW(write_final_csv(tmp.path() / "final.csv", s), Error);
}

TEST(FinalCsv, BodyColumnNamesEachTrianglesBody) {
  test::TempDir tmp;
  write_final_csv(tmp.path() / "final.csv", bodies_snapshot());
  const auto lines = test::read_lines(tmp.path() / "final.csv");
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "id,x,y,theta,vx,vy,omega,x1,y1,x2,y2,x3,y3,body");
  const double body[5] = {0, 0, 1, 1, 2};
  for (std::size_t k = 0; k < 5; ++k) {
    const std::vector<double> row = test::numbers(lines[1 + k]);
    ASSERT_EQ(row.size(), 14u);
    EXPECT_EQ(row[13], body[k]) << "triangle " << k;
  }
}

TEST(Vtu, BodyArrayRoundTrips) {
  test::TempDir tmp;
  const Snapshot s = bodies_snapshot();
  for (const Encoding e : {Encoding::Binary, Encoding::Ascii}) {
    write_vtu_frame(tmp.path() / "frame.vtu", s, {e});
    EXPECT_NE(test::read_file(tmp.path() / "frame.vtu").find("Name=\"body\""), std::string::npos);
    const Snapshot r = read_vtu_frame(tmp.path() / "frame.vtu");
    EXPECT_EQ(r.member_body, s.member_body);
    EXPECT_EQ(r.body_first, s.body_first);
    EXPECT_EQ(r.body_count(), 3u);
    EXPECT_TRUE(r.body_x.empty()) << "a frame does not hold the bodies' own columns";
  }
}

TEST(Vtu, FrameOfLoneTrianglesReadsBodiless) {
  test::TempDir tmp;
  const auto file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, test::sample_snapshot(), {Encoding::Ascii});
  const std::string text = test::read_file(file);
  EXPECT_NE(text.find("Name=\"body\""), std::string::npos);  // 0 1 2: their own ids
  EXPECT_TRUE(read_vtu_frame(file).member_body.empty());
  // A frame written before bodies existed has no body array at all.
  const auto at = text.rfind("<DataArray", text.find("Name=\"body\""));
  ASSERT_NE(at, std::string::npos);
  const auto end = text.find("</DataArray>", at) + std::string("</DataArray>").size();
  std::string old = text;
  old.erase(at, end - at);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << old;
  const Snapshot r = read_vtu_frame(file);
  EXPECT_EQ(r.size(), 3u);
  EXPECT_TRUE(r.member_body.empty());
  EXPECT_EQ(r.body_count(), 3u);
}

TEST(Vtu, BodyOfScatteredMembersIsRefused) {
  test::TempDir tmp;
  const auto file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, bodies_snapshot(), {Encoding::Ascii});
  std::string text = test::read_file(file);
  // body 0 1 0 1 2: a body's members are consecutive triangles.
  const auto at = text.find("Name=\"body\"");
  const auto values = text.find("0 0 1 1 2", at);
  ASSERT_NE(values, std::string::npos) << text.substr(at, 200);
  text.replace(values, 9, "0 1 0 1 2");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  try {
    read_vtu_frame(file);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("consecutive"), std::string::npos) << e.what();
  }
}

// --- render --color body ---

struct Pixel {
  int r, g, b;
  bool operator==(const Pixel&) const = default;
};

Pixel pixel(const std::filesystem::path& png, double fx, double fy) {
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create_from_png(png.c_str()), cairo_surface_destroy);
  EXPECT_EQ(cairo_surface_status(surface.get()), CAIRO_STATUS_SUCCESS);
  const int x = static_cast<int>(fx * cairo_image_surface_get_width(surface.get()));
  const int y = static_cast<int>(fy * cairo_image_surface_get_height(surface.get()));
  const unsigned char* row =
      cairo_image_surface_get_data(surface.get()) +
      static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(surface.get());
  std::uint32_t argb;
  std::memcpy(&argb, row + 4 * x, sizeof argb);
  return {int(argb >> 16 & 255), int(argb >> 8 & 255), int(argb & 255)};
}

TEST(Render, ColourByBodyGivesTouchingBodiesDistinctColoursAndOneToEachBody) {
  test::TempDir tmp;
  Snapshot s = bodies_snapshot();
  s.x1[4] = s.x2[4] = s.x3[4] = 0;  // the wall shrunk to a corner: the image is [0, 2] x [0, 1]
  s.y1[4] = s.y2[4] = s.y3[4] = 0;
  RenderOptions o;
  o.width = 400;
  o.margin = 0;
  o.color_by = RenderOptions::ColorBy::Body;
  render_png(s, tmp.path() / "a.png", o);
  // Image fractions: x / 2 across, 1 - y down.
  const auto at = [&](double x, double y) { return pixel(tmp.path() / "a.png", x / 2, 1 - y); };
  const Pixel lower0 = at(0.75, 0.2), upper0 = at(0.25, 0.8);  // body 0's two members
  const Pixel lower1 = at(1.75, 0.2), upper1 = at(1.25, 0.8);
  EXPECT_EQ(lower0, upper0) << "one colour per body";
  EXPECT_EQ(lower1, upper1);
  EXPECT_NE(lower0, lower1) << "bodies that touch differ";
  // The members' shared diagonal is not outlined: its middle has the body's colour, up to
  // the anti-aliasing of the two fills that meet there (a few levels of 255; an outline
  // would be dark).
  const Pixel diagonal = at(0.5, 0.5);
  EXPECT_NEAR(diagonal.r, lower0.r, 12);
  EXPECT_NEAR(diagonal.g, lower0.g, 12);
  EXPECT_NEAR(diagonal.b, lower0.b, 12);
  // The outline between the two bodies is drawn (dark), as is a body's outer edge.
  const Pixel edge = at(1.0, 0.5);
  EXPECT_LT(edge.r + edge.g + edge.b, lower0.r + lower0.g + lower0.b);
}

TEST(BodyColors, NeighboursInAChainAndAGridDiffer) {
  // A 6 x 5 grid of unit squares, each a body of two triangles, touching its neighbours.
  Snapshot s;
  const int nx = 6, ny = 5;
  s.resize(2 * nx * ny);
  s.resize_bodies(nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t b = static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i);
      const double x = i, y = j;
      const double tris[2][6] = {{x, y, x + 1, y, x + 1, y + 1}, {x, y, x + 1, y + 1, x, y + 1}};
      for (std::size_t m = 0; m < 2; ++m) {
        const std::size_t k = 2 * b + m;
        s.x1[k] = tris[m][0], s.y1[k] = tris[m][1], s.x2[k] = tris[m][2];
        s.y2[k] = tris[m][3], s.x3[k] = tris[m][4], s.y3[k] = tris[m][5];
        s.member_body[k] = static_cast<std::int32_t>(b);
      }
      s.body_first[b + 1] = static_cast<std::int64_t>(2 * b + 2);
    }
  const std::vector<int> c = io::body_colors(s, 0.05, 12);
  ASSERT_EQ(c.size(), static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int b = j * nx + i;
      EXPECT_GE(c[b], 0);
      EXPECT_LT(c[b], 12);
      // Every one of the 8 around it touches it (corners included).
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if ((di || dj) && ii >= 0 && ii < nx && jj >= 0 && jj < ny) {
            EXPECT_NE(c[b], c[jj * nx + ii]) << i << "," << j << " and " << ii << "," << jj;
          }
        }
    }
  // Each square's diagonal is inside its body; its four sides are outlines.
  const auto inner = io::inner_edges(s);
  for (std::size_t k = 0; k < s.size(); ++k)
    EXPECT_EQ(inner[k], k % 2 == 0 ? 0b100 : 0b001) << k;  // the diagonal: edge 2 or edge 0
}

// --- a run of a known scene ---

constexpr const char* kScene = R"(
[simulation]
steps = 200
dt = 1e-5
gravity = [0, -9.81]
backend = "cpu"
[output]
every = 100
contacts = false
[[material]]
name = "m"
density = 2000
penalty = 1e8
friction = 0.5
restitution = 0.5
[[triangle]]
material = "m"
vertices = [[1, -0.1], [-1, -0.1], [0, -1]]
fixed = true
[[body]]
material = "m"
triangles = [[[0, 0], [0.1, 0], [0.1, 0.1]], [[0, 0], [0.1, 0.1], [0, 0.1]]]
velocity = [0.5, 0]
angular_velocity = 2
[[triangle]]
material = "m"
vertices = [[0.3, 0], [0.4, 0], [0.3, 0.1]]
)";

TEST(BodyOutputs, RunWritesBodiesFinalAndFramesOfAKnownScene) {
  test::TempDir tmp;
  Scene scene = parse_scene(kScene, "known");
  scene.output.dir = tmp.path().string();
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  o.force = true;
  run_scene(scene, o);

  // bodies.csv: the floor, the square (2 members, mass 2000 · 0.01, inertia m a² / 6 about
  // its centre) and the lone triangle (mass 2000 · 0.005).
  const auto bodies = test::read_lines(tmp.path() / "bodies.csv");
  ASSERT_EQ(bodies.size(), 4u);
  const auto floor = test::numbers(bodies[1]), square = test::numbers(bodies[2]),
             lone = test::numbers(bodies[3]);
  EXPECT_EQ(floor[0], 0);
  EXPECT_EQ(floor[7], 0) << "a wall's mass is 0";
  EXPECT_EQ(floor[9], 1);
  EXPECT_EQ(square[0], 1);
  EXPECT_NEAR(square[7], 20, 1e-12);
  EXPECT_NEAR(square[8], 20 * 0.01 / 6, 1e-14);
  EXPECT_EQ(square[9], 2);
  EXPECT_EQ(lone[9], 1);
  EXPECT_NEAR(lone[7], 10, 1e-12);
  // Free flight for 2 ms (nothing touches): the square's centre has moved with its velocity
  // and turned at 2 rad/s.
  const double t = 200 * 1e-5;
  EXPECT_NEAR(square[1], 0.05 + 0.5 * t, 1e-12);
  EXPECT_NEAR(square[2], 0.05 - 0.5 * 9.81 * t * t, 1e-6);
  EXPECT_NEAR(square[3], 2 * t, 1e-12);
  EXPECT_NEAR(square[6], 2, 1e-12);
  EXPECT_NEAR(square[4], 0.5, 1e-12);

  // final.csv: triangles 0..3, in bodies 0, 1, 1, 2.
  const auto final_rows = test::read_lines(tmp.path() / "final.csv");
  ASSERT_EQ(final_rows.size(), 5u);
  const double body_of[4] = {0, 1, 1, 2};
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_EQ(test::numbers(final_rows[1 + k]).back(), body_of[k]);

  // The frames carry the body of each triangle.
  const Snapshot frame = read_vtu_frame(tmp.path() / "frames" / "frame_000000200.vtu");
  EXPECT_EQ(frame.member_body, (std::vector<std::int32_t>{0, 1, 1, 2}));
  EXPECT_EQ(frame.body_first, (std::vector<std::int64_t>{0, 1, 3, 4}));
  // And render colours them (the two free bodies are far apart: any colours will do).
  RenderOptions r;
  r.color_by = RenderOptions::ColorBy::Body;
  render_png(frame, tmp.path() / "frame.png", r);
  EXPECT_TRUE(std::filesystem::is_regular_file(tmp.path() / "frame.png"));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
