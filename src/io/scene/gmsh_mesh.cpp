// Reading a 2D Gmsh mesh through Gmsh's own C++ API (Debian's libgmsh-dev), so that every
// .msh version Gmsh writes is read by the code that wrote it. Gmsh keeps one global
// model: each read initialises it, opens the file, copies what tridem needs and
// finalises it again, so reads are independent (and not to be run from two threads).
// Part of the Gmsh module (gmsh_module_entry.cpp), not of tridem_core.
#include "io/scene/gmsh_mesh.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <exception>
#include <unordered_map>
#include <vector>

namespace tridem::gmsh_module {
namespace {

using scene_detail::ImportedParticles;
using scene_detail::MeshRegion;

constexpr int kTriangle3 = 2;  // Gmsh's element type of a 3-node triangle

// Gmsh initialised for one read, quiet, throwing on errors; finalised however it ends.
struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.AbortOnError", 3);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

ImportedParticles read_open_mesh(const std::string& name,
                                 const std::vector<std::string>& body_groups) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  for (int type : types)
    if (type != kTriangle3) {
      std::string what;
      int dim = 0, order = 0, nodes = 0, primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(type, what, dim, order, nodes, local, primary);
      throw SceneError(fmt::format(
          "{}: the mesh has 2D elements of type {} ({}); tridem reads 3-node triangles only "
          "(mesh with triangles of order 1: Mesh.ElementOrder = 1, no recombination)",
          name, type, what));
    }
  std::vector<std::size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(kTriangle3, element_tags, element_nodes);
  if (element_tags.empty())
    throw SceneError(fmt::format("{}: the mesh has no triangles (is it meshed in 2D?)", name));

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, Vec2d> node_at;
  node_at.reserve(node_tags.size());
  for (std::size_t k = 0; k < node_tags.size(); ++k) {
    const double z = coords[3 * k + 2];
    if (z != 0)
      throw SceneError(fmt::format("{}: node {} has z = {}; tridem reads meshes in the plane z = 0",
                                   name, node_tags[k], z));
    node_at[node_tags[k]] = {coords[3 * k], coords[3 * k + 1]};
  }

  // Element tag -> index of its body group.
  std::unordered_map<std::size_t, std::int64_t> body_of;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (std::size_t b = 0; b < body_groups.size(); ++b) {
    bool found = false;
    for (const auto& [dim, tag] : groups) {
      std::string group_name;
      gmsh::model::getPhysicalName(dim, tag, group_name);
      if (group_name != body_groups[b]) continue;
      found = true;
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      for (int entity : entities) {
        std::vector<std::size_t> tags, nodes;
        gmsh::model::mesh::getElementsByType(kTriangle3, tags, nodes, entity);
        for (std::size_t t : tags)
          if (!body_of.emplace(t, static_cast<std::int64_t>(b)).second &&
              body_of[t] != static_cast<std::int64_t>(b))
            throw SceneError(fmt::format(
                "{}: triangle element {} is in two body groups, \"{}\" and \"{}\"", name, t,
                body_groups[static_cast<std::size_t>(body_of[t])], body_groups[b]));
      }
    }
    if (!found) {
      std::string known;
      for (const auto& [dim, tag] : groups) {
        std::string group_name;
        gmsh::model::getPhysicalName(dim, tag, group_name);
        known += (known.empty() ? "\"" : ", \"") + group_name + "\"";
      }
      throw SceneError(fmt::format("{}: no 2D physical group named \"{}\" (the mesh has {})", name,
                                   body_groups[b], known.empty() ? "none" : known));
    }
  }

  ImportedParticles out;
  out.where_name = "element";
  for (std::size_t e = 0; e < element_tags.size(); ++e) {
    std::array<Vec2d, 3> v{};
    for (std::size_t k = 0; k < 3; ++k) v[k] = node_at.at(element_nodes[3 * e + k]);
    out.vertices.push_back(v);
    out.velocity.push_back({});
    out.angular_velocity.push_back(0);
    const auto it = body_of.find(element_tags[e]);
    out.body.push_back(it == body_of.end() ? -1 : it->second);
    out.where.push_back(element_tags[e]);
  }
  return out;
}

}  // namespace

ImportedParticles mesh(const MeshRegion& region, const std::string& what) {
  try {
    GmshSession session;
    gmsh::option::setNumber("General.NumThreads", 1);
    // Delaunay, not Frontal-Delaunay: the frontal mesher lays near-equilateral triangles in
    // lattice-like patches whose edges take three directions only (a Brazilian disc meshed
    // so had no edge within 25 degrees of its loaded diameter: docs/fracture.md, "Why the
    // first disc was low"); Delaunay's edges take every direction.
    gmsh::option::setNumber("Mesh.Algorithm", 5);
    gmsh::option::setNumber("Mesh.MeshSizeMin", region.size);
    gmsh::option::setNumber("Mesh.MeshSizeMax", region.size);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::add("tridem");
    namespace geo = gmsh::model::geo;
    if (region.kind == MeshRegion::Kind::Disc && region.flat_angle > 0) {
      // A flattened disc: two chords of half-width r sin(a/2) at y = +-r cos(a/2), joined by
      // the two side arcs (each under 180 degrees, as Gmsh's arcs must be).
      const double cx = region.center.x, cy = region.center.y, r = region.radius;
      const double sx = r * std::sin(0.5 * region.flat_angle);
      const double sy = r * std::cos(0.5 * region.flat_angle);
      const int c = geo::addPoint(cx, cy, 0);
      const int p[4] = {geo::addPoint(cx + sx, cy + sy, 0), geo::addPoint(cx - sx, cy + sy, 0),
                        geo::addPoint(cx - sx, cy - sy, 0), geo::addPoint(cx + sx, cy - sy, 0)};
      geo::addPlaneSurface(
          {geo::addCurveLoop({geo::addLine(p[0], p[1]), geo::addCircleArc(p[1], c, p[2]),
                              geo::addLine(p[2], p[3]), geo::addCircleArc(p[3], c, p[0])})});
    } else if (region.kind == MeshRegion::Kind::Disc) {
      // Four quarter arcs, so that nodes sit exactly at the disc's extremes in x and y:
      // where a platen of a Brazilian test touches it.
      const double cx = region.center.x, cy = region.center.y, r = region.radius;
      const int c = geo::addPoint(cx, cy, 0);
      const int p[4] = {geo::addPoint(cx + r, cy, 0), geo::addPoint(cx, cy + r, 0),
                        geo::addPoint(cx - r, cy, 0), geo::addPoint(cx, cy - r, 0)};
      std::vector<int> arcs;
      for (int k = 0; k < 4; ++k) arcs.push_back(geo::addCircleArc(p[k], c, p[(k + 1) % 4]));
      geo::addPlaneSurface({geo::addCurveLoop(arcs)});
    } else {
      // A rectangle is the polygon of its four corners; every outline is meshed alike.
      const double x0 = region.lo.x, y0 = region.lo.y, x1 = region.hi.x, y1 = region.hi.y;
      const std::vector<Vec2d> outline =
          region.kind == MeshRegion::Kind::Polygon
              ? region.polygon
              : std::vector<Vec2d>{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
      std::vector<int> points, sides;
      for (const Vec2d& v : outline) points.push_back(geo::addPoint(v.x, v.y, 0));
      for (std::size_t k = 0; k < points.size(); ++k)
        sides.push_back(geo::addLine(points[k], points[(k + 1) % points.size()]));
      geo::addPlaneSurface({geo::addCurveLoop(sides)});
    }
    geo::synchronize();
    gmsh::model::mesh::generate(2);
    return read_open_mesh(what, {});
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(fmt::format("{}: Gmsh cannot mesh it: {}", what, e.what()));
  } catch (const std::string& e) {
    throw SceneError(fmt::format("{}: Gmsh cannot mesh it: {}", what, e));
  } catch (...) {
    throw SceneError(fmt::format("{}: Gmsh cannot mesh it", what));
  }
}

ImportedParticles read_mesh(const std::filesystem::path& file,
                            const std::vector<std::string>& body_groups) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw SceneError(fmt::format("{}: cannot read the mesh: no such file", name));
  try {
    GmshSession session;
    gmsh::open(name);
    return read_open_mesh(name, body_groups);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(fmt::format("{}: Gmsh cannot read it: {}", name, e.what()));
  } catch (const std::string& e) {
    throw SceneError(fmt::format("{}: Gmsh cannot read it: {}", name, e));
  } catch (...) {
    throw SceneError(fmt::format("{}: Gmsh cannot read it as a mesh", name));
  }
}

}  // namespace tridem::gmsh_module
