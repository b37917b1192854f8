#include "core/mesh/structured_rectangle.h"

#include <gmsh.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/mesh/gmsh_session.h"

namespace thinlayer {

namespace {

void validate(const RectangleMeshSpec& spec) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("structured_rectangle: " + what);
  };
  if (spec.nx < 1 || spec.ny < 1)
    fail("nx and ny must be >= 1 (got nx=" + std::to_string(spec.nx) +
         ", ny=" + std::to_string(spec.ny) + ")");
  // Node indices are ints.
  if ((static_cast<double>(spec.nx) + 1) * (static_cast<double>(spec.ny) + 1) >
      std::numeric_limits<int>::max())
    fail("too many nodes (nx=" + std::to_string(spec.nx) + ", ny=" + std::to_string(spec.ny) + ")");
  if (!std::isfinite(spec.x0) || !std::isfinite(spec.y0))
    fail("the corner (x0, y0) must be finite (got " + std::to_string(spec.x0) + ", " +
         std::to_string(spec.y0) + ")");
  if (!(std::isfinite(spec.width) && spec.width > 0) ||
      !(std::isfinite(spec.height) && spec.height > 0))
    fail("width and height must be finite and > 0 (got width=" + std::to_string(spec.width) +
         ", height=" + std::to_string(spec.height) + ")");
}

struct RectangleTags {
  int bottom_left, bottom_right, top_right, top_left;  // points
  int bottom, right, top, left;                        // curves
  int surface;
};

// Bottom and top run along +x, left and right along +y, so that sorting a side's nodes by
// curve parameter sorts them by increasing x or y.
RectangleTags add_rectangle(const RectangleMeshSpec& s) {
  namespace geo = gmsh::model::geo;
  RectangleTags t{};
  t.bottom_left = geo::addPoint(s.x0, s.y0, 0);
  t.bottom_right = geo::addPoint(s.x0 + s.width, s.y0, 0);
  t.top_right = geo::addPoint(s.x0 + s.width, s.y0 + s.height, 0);
  t.top_left = geo::addPoint(s.x0, s.y0 + s.height, 0);
  t.bottom = geo::addLine(t.bottom_left, t.bottom_right);
  t.right = geo::addLine(t.bottom_right, t.top_right);
  t.top = geo::addLine(t.top_left, t.top_right);
  t.left = geo::addLine(t.bottom_left, t.top_left);
  const int loop = geo::addCurveLoop({t.bottom, t.right, -t.top, -t.left});
  t.surface = geo::addPlaneSurface({loop});
  return t;
}

void set_structured_meshing(const RectangleMeshSpec& s, const RectangleTags& t) {
  namespace geo = gmsh::model::geo;
  geo::mesh::setTransfiniteCurve(t.bottom, s.nx + 1);
  geo::mesh::setTransfiniteCurve(t.top, s.nx + 1);
  geo::mesh::setTransfiniteCurve(t.right, s.ny + 1);
  geo::mesh::setTransfiniteCurve(t.left, s.ny + 1);
  // gmsh's arrangement is relative to the corner order: with the corners listed
  // counter-clockwise from the bottom-left one, "Right" splits along "/", as TriangleDiagonal.
  const char* arrangement = s.diagonal == TriangleDiagonal::Right ? "Right" : "Left";
  geo::mesh::setTransfiniteSurface(t.surface, arrangement,
                                   {t.bottom_left, t.bottom_right, t.top_right, t.top_left});
  if (s.element == ElementType::Q1) geo::mesh::setRecombine(2, t.surface);
}

std::vector<NamedBoundary> rectangle_boundaries(const RectangleTags& t) {
  return {{"bottom", 1, {t.bottom}},
          {"right", 1, {t.right}},
          {"top", 1, {t.top}},
          {"left", 1, {t.left}},
          {"bottom_left", 0, {t.bottom_left}},
          {"bottom_right", 0, {t.bottom_right}},
          {"top_right", 0, {t.top_right}},
          {"top_left", 0, {t.top_left}}};
}

// gmsh places transfinite nodes by interpolation, off the exact grid by round-off. Moving
// them onto x0 + i*width/nx makes meshes bit-reproducible and symmetric; a node far from
// any grid position means gmsh did not build the expected grid.
double snap(double value, double origin, double length, int n) {
  const double index = std::round((value - origin) / length * n);
  const double exact = origin + index * length / n;
  const double tolerance = 1e-6 * length / n + 1e-12 * (std::abs(origin) + length);
  if (index < 0 || index > n || std::abs(value - exact) > tolerance)
    throw std::runtime_error("structured_rectangle: gmsh put a node off the structured grid");
  return exact;
}

void snap_to_grid(const RectangleMeshSpec& s, Mesh& mesh) {
  for (Eigen::Index i = 0; i < mesh.nodes.rows(); ++i) {
    mesh.nodes(i, 0) = snap(mesh.nodes(i, 0), s.x0, s.width, s.nx);
    mesh.nodes(i, 1) = snap(mesh.nodes(i, 1), s.y0, s.height, s.ny);
  }
}

void check_counts(const RectangleMeshSpec& s, const Mesh& mesh) {
  const int cells_per_quad = s.element == ElementType::Q1 ? 1 : 2;
  if (mesh.element != s.element || mesh.num_nodes() != (s.nx + 1) * (s.ny + 1) ||
      mesh.num_cells() != cells_per_quad * s.nx * s.ny)
    throw std::runtime_error("structured_rectangle: gmsh did not produce the requested " +
                             std::to_string(s.nx) + "x" + std::to_string(s.ny) + " " +
                             to_string(s.element) + " grid");
}

}  // namespace

Mesh structured_rectangle(const RectangleMeshSpec& spec) {
  validate(spec);
  GmshModelScope scope("structured_rectangle");
  Mesh mesh = with_gmsh_errors([&] {
    const RectangleTags tags = add_rectangle(spec);
    set_structured_meshing(spec, tags);
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(2);
    return mesh_from_gmsh({tags.surface}, rectangle_boundaries(tags));
  });
  check_counts(spec, mesh);
  snap_to_grid(spec, mesh);
  return mesh;
}

}  // namespace thinlayer
