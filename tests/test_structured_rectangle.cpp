// Structured rectangle meshes (core/mesh/structured_rectangle.h) and the gmsh -> Mesh
// conversion they rely on (core/mesh/gmsh_session.h).
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/gmsh_session.h"
#include "core/mesh/structured_rectangle.h"

namespace thinlayer {
namespace {

using DirectedEdge = std::pair<int, int>;

// Each cell side in its cell's order, i.e. with that cell on its left.
std::set<DirectedEdge> directed_cell_sides(const Mesh& mesh) {
  std::set<DirectedEdge> sides;
  auto add = [&](const auto& cell) {
    for (std::size_t k = 0; k < cell.size(); ++k)
      sides.insert({cell[k], cell[(k + 1) % cell.size()]});
  };
  for (const auto& q : mesh.quads) add(q);
  for (const auto& t : mesh.triangles) add(t);
  return sides;
}

template <class Cell>
double signed_area(const Mesh& mesh, const Cell& cell) {
  double twice = 0;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const int a = cell[k], b = cell[(k + 1) % cell.size()];
    twice += mesh.nodes(a, 0) * mesh.nodes(b, 1) - mesh.nodes(b, 0) * mesh.nodes(a, 1);
  }
  return 0.5 * twice;
}

std::vector<double> cell_areas(const Mesh& mesh) {
  std::vector<double> areas;
  for (const auto& q : mesh.quads) areas.push_back(signed_area(mesh, q));
  for (const auto& t : mesh.triangles) areas.push_back(signed_area(mesh, t));
  return areas;
}

// Every edge of the set is a boundary side with a cell on its left.
void expect_body_on_left(const Mesh& mesh, const std::string& set) {
  const auto sides = directed_cell_sides(mesh);
  for (const auto& [a, b] : mesh.edge_set(set)) {
    EXPECT_TRUE(sides.count({a, b}))
        << set << ": edge " << a << "->" << b << " has no cell on its left";
    EXPECT_FALSE(sides.count({b, a}))
        << set << ": edge " << a << "->" << b << " is not on the boundary";
  }
}

RectangleMeshSpec spec_of(ElementType element,
                          TriangleDiagonal diagonal = TriangleDiagonal::Right) {
  return {.x0 = -1.5, .y0 = 2.0, .width = 3.0, .height = 0.7, .nx = 5, .ny = 3, .element = element, .diagonal = diagonal};
}

// The diagonals of a P1 mesh, as their slope signs: +1 for "/", -1 for "\".
std::vector<int> diagonal_slopes(const Mesh& mesh) {
  std::vector<int> slopes;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const double dx = mesh.nodes(t[(k + 1) % 3], 0) - mesh.nodes(t[k], 0);
      const double dy = mesh.nodes(t[(k + 1) % 3], 1) - mesh.nodes(t[k], 1);
      if (dx != 0 && dy != 0) slopes.push_back(dx * dy > 0 ? +1 : -1);
    }
  }
  return slopes;
}

// Runs first (tests run in file order), so gmsh's initialisation is captured too.
TEST(StructuredRectangle, MeshingPrintsNothing) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  structured_rectangle(spec_of(ElementType::Q1));
  structured_rectangle(spec_of(ElementType::P1, TriangleDiagonal::Left));
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
}

TEST(StructuredRectangle, Q1Counts) {
  const Mesh mesh = structured_rectangle(spec_of(ElementType::Q1));
  EXPECT_EQ(mesh.element, ElementType::Q1);
  EXPECT_EQ(mesh.num_nodes(), 6 * 4);
  EXPECT_EQ(mesh.num_cells(), 5 * 3);
  EXPECT_TRUE(mesh.triangles.empty());
}

TEST(StructuredRectangle, P1CountsForBothDiagonals) {
  for (auto diagonal : {TriangleDiagonal::Right, TriangleDiagonal::Left}) {
    const Mesh mesh = structured_rectangle(spec_of(ElementType::P1, diagonal));
    EXPECT_EQ(mesh.element, ElementType::P1);
    EXPECT_EQ(mesh.num_nodes(), 6 * 4);
    EXPECT_EQ(mesh.num_cells(), 2 * 5 * 3);
    EXPECT_TRUE(mesh.quads.empty());
  }
}

TEST(StructuredRectangle, DiagonalsFollowTheSpec) {
  const auto right =
      diagonal_slopes(structured_rectangle(spec_of(ElementType::P1, TriangleDiagonal::Right)));
  const auto left =
      diagonal_slopes(structured_rectangle(spec_of(ElementType::P1, TriangleDiagonal::Left)));
  // Each diagonal is shared by two triangles.
  ASSERT_EQ(right.size(), 2u * 5 * 3);
  ASSERT_EQ(left.size(), 2u * 5 * 3);
  EXPECT_TRUE(std::all_of(right.begin(), right.end(), [](int s) { return s == +1; }))
      << "Right is \"/\"";
  EXPECT_TRUE(std::all_of(left.begin(), left.end(), [](int s) { return s == -1; }))
      << "Left is \"\\\"";
}

TEST(StructuredRectangle, SingleCell) {
  RectangleMeshSpec spec;  // unit square, 1 x 1
  const Mesh q1 = structured_rectangle(spec);
  EXPECT_EQ(q1.num_nodes(), 4);
  EXPECT_EQ(q1.num_cells(), 1);
  spec.element = ElementType::P1;
  const Mesh p1 = structured_rectangle(spec);
  EXPECT_EQ(p1.num_nodes(), 4);
  EXPECT_EQ(p1.num_cells(), 2);
  EXPECT_EQ(p1.node_set("bottom").size(), 2u);
  EXPECT_EQ(p1.edge_set("left").size(), 1u);
}

TEST(StructuredRectangle, InvalidInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto with = [](auto change) {
    RectangleMeshSpec spec;
    change(spec);
    return spec;
  };
  EXPECT_THROW(structured_rectangle(with([](auto& s) { s.nx = 0; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([](auto& s) { s.ny = -2; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([](auto& s) { s.width = 0; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([](auto& s) { s.height = -1; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([&](auto& s) { s.width = nan; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([&](auto& s) { s.height = inf; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([&](auto& s) { s.x0 = nan; })), std::invalid_argument);
  EXPECT_THROW(structured_rectangle(with([](auto& s) { s.nx = s.ny = 1 << 20; })),
               std::invalid_argument);
  // gmsh is still usable after a rejected spec.
  EXPECT_EQ(structured_rectangle(RectangleMeshSpec{}).num_cells(), 1);
}

// Geometry and named sets, for every element type and diagonal.
// Each test: the rectangle of the parameter, meshed; (x1, y1) its top-right corner.
class RectangleGeometry : public testing::TestWithParam<RectangleMeshSpec> {
 protected:
  const RectangleMeshSpec spec = GetParam();
  const Mesh mesh = structured_rectangle(spec);
  const double x1 = spec.x0 + spec.width, y1 = spec.y0 + spec.height;
};

TEST_P(RectangleGeometry, CellsAreCounterClockwiseAndTileTheRectangle) {
  double total = 0;
  for (double area : cell_areas(mesh)) {
    EXPECT_GT(area, 0);
    total += area;
  }
  EXPECT_NEAR(total, spec.width * spec.height, 1e-12 * spec.width * spec.height);
}

TEST_P(RectangleGeometry, NodesAreExactGridPointsOnce) {
  std::set<std::pair<int, int>> seen;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const int i =
        static_cast<int>(std::lround((mesh.nodes(n, 0) - spec.x0) / spec.width * spec.nx));
    const int j =
        static_cast<int>(std::lround((mesh.nodes(n, 1) - spec.y0) / spec.height * spec.ny));
    ASSERT_TRUE(i >= 0 && i <= spec.nx && j >= 0 && j <= spec.ny) << "node " << n;
    EXPECT_DOUBLE_EQ(mesh.nodes(n, 0), spec.x0 + i * spec.width / spec.nx);
    EXPECT_DOUBLE_EQ(mesh.nodes(n, 1), spec.y0 + j * spec.height / spec.ny);
    EXPECT_TRUE(seen.insert({i, j}).second) << "two nodes at grid point " << i << ", " << j;
  }
  EXPECT_EQ(static_cast<int>(seen.size()), (spec.nx + 1) * (spec.ny + 1));
}

TEST_P(RectangleGeometry, SideNodeSetsAreSortedAndComplete) {
  struct Side {
    const char* name;
    int along;        // coordinate increasing along the set
    int across;       // coordinate constant on the side
    double position;  // its value
    int size;
  };
  for (const Side side :
       {Side{"bottom", 0, 1, spec.y0, spec.nx + 1}, Side{"top", 0, 1, y1, spec.nx + 1},
        Side{"left", 1, 0, spec.x0, spec.ny + 1}, Side{"right", 1, 0, x1, spec.ny + 1}}) {
    const auto& nodes = mesh.node_set(side.name);
    ASSERT_EQ(static_cast<int>(nodes.size()), side.size) << side.name;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      EXPECT_DOUBLE_EQ(mesh.nodes(nodes[k], side.across), side.position)
          << side.name << " node " << k;
      if (k > 0) {
        EXPECT_LT(mesh.nodes(nodes[k - 1], side.along), mesh.nodes(nodes[k], side.along))
            << side.name;
      }
    }
  }
}

TEST_P(RectangleGeometry, CornerSetsHoldTheCornerNode) {
  struct Corner {
    const char* name;
    double x, y;
    int node_from_sides;
  };
  const auto& bottom = mesh.node_set("bottom");
  const auto& top = mesh.node_set("top");
  for (const Corner c :
       {Corner{"bottom_left", spec.x0, spec.y0, bottom.front()},
        Corner{"bottom_right", x1, spec.y0, bottom.back()}, Corner{"top_right", x1, y1, top.back()},
        Corner{"top_left", spec.x0, y1, top.front()}}) {
    const auto& set = mesh.node_set(c.name);
    ASSERT_EQ(set.size(), 1u) << c.name;
    EXPECT_DOUBLE_EQ(mesh.nodes(set[0], 0), c.x) << c.name;
    EXPECT_DOUBLE_EQ(mesh.nodes(set[0], 1), c.y) << c.name;
    EXPECT_EQ(set[0], c.node_from_sides) << c.name;
  }
  EXPECT_EQ(mesh.node_set("left").front(), mesh.node_set("bottom_left")[0]);
  EXPECT_EQ(mesh.node_set("right").back(), mesh.node_set("top_right")[0]);
}

TEST_P(RectangleGeometry, EdgeSetsRunCounterClockwise) {
  struct Side {
    const char* name;
    int dx_sign, dy_sign;
    int size;
  };
  for (const Side side : {Side{"bottom", +1, 0, spec.nx}, Side{"right", 0, +1, spec.ny},
                          Side{"top", -1, 0, spec.nx}, Side{"left", 0, -1, spec.ny}}) {
    const auto& edges = mesh.edge_set(side.name);
    const auto& nodes = mesh.node_set(side.name);
    ASSERT_EQ(static_cast<int>(edges.size()), side.size) << side.name;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const auto [a, b] = edges[k];
      const double dx = mesh.nodes(b, 0) - mesh.nodes(a, 0),
                   dy = mesh.nodes(b, 1) - mesh.nodes(a, 1);
      EXPECT_EQ((dx > 0) - (dx < 0), side.dx_sign) << side.name << " edge " << k;
      EXPECT_EQ((dy > 0) - (dy < 0), side.dy_sign) << side.name << " edge " << k;
      // Listed in the order of the node set.
      EXPECT_TRUE((a == nodes[k] && b == nodes[k + 1]) || (a == nodes[k + 1] && b == nodes[k]))
          << side.name << " edge " << k;
    }
    expect_body_on_left(mesh, side.name);
  }
}

RectangleMeshSpec with_element(RectangleMeshSpec spec, ElementType element,
                               TriangleDiagonal diagonal) {
  spec.element = element;
  spec.diagonal = diagonal;
  return spec;
}

RectangleMeshSpec far_from_origin() {
  return {.x0 = 1e4, .y0 = -3e3, .width = 0.1, .height = 2.5, .nx = 7, .ny = 11};
}

INSTANTIATE_TEST_SUITE_P(
    ElementsAndDiagonals, RectangleGeometry,
    testing::Values(spec_of(ElementType::Q1), spec_of(ElementType::P1, TriangleDiagonal::Right),
                    spec_of(ElementType::P1, TriangleDiagonal::Left),
                    with_element(far_from_origin(), ElementType::Q1, TriangleDiagonal::Right),
                    with_element(far_from_origin(), ElementType::P1, TriangleDiagonal::Left),
                    with_element(RectangleMeshSpec{}, ElementType::P1, TriangleDiagonal::Right)),
    [](const testing::TestParamInfo<RectangleMeshSpec>& info) {
      const RectangleMeshSpec& s = info.param;
      std::string name = std::to_string(info.index) + "_" + to_string(s.element);
      if (s.element == ElementType::P1) name += s.diagonal == TriangleDiagonal::Right ? "_right" : "_left";
      return name + "_" + std::to_string(s.nx) + "x" + std::to_string(s.ny);
    });

// mesh_from_gmsh on what the dovetail will need: slanted curves, several bodies, a surface
// whose cells gmsh orients clockwise.
class GmshExtraction : public testing::Test {
 protected:
  struct Body {
    int surface;
    int slanted;  // a slanted curve on its boundary
    int corner;   // a point on its boundary
  };

  // A parallelogram with slanted sides (its curve loop given clockwise) and, apart from it,
  // a triangle; unstructured triangles, or quads if `recombine`.
  void build(bool recombine) {
    namespace geo = gmsh::model::geo;
    const double h = 0.15;
    const int a = geo::addPoint(0, 0, 0, h), b = geo::addPoint(2, 0, 0, h),
              c = geo::addPoint(2.6, 1, 0, h), d = geo::addPoint(0.6, 1, 0, h);
    const int ab = geo::addLine(a, b), bc = geo::addLine(b, c), cd = geo::addLine(c, d),
              da = geo::addLine(d, a);
    parallelogram = {geo::addPlaneSurface({geo::addCurveLoop({-da, -cd, -bc, -ab})}), bc, a};
    const int e = geo::addPoint(4, 0, 0, h), f = geo::addPoint(5, 0, 0, h),
              g = geo::addPoint(4, 1.5, 0, h);
    const int ef = geo::addLine(e, f), fg = geo::addLine(f, g), ge = geo::addLine(g, e);
    triangle = {geo::addPlaneSurface({geo::addCurveLoop({ef, fg, ge})}), fg, g};
    if (recombine) {
      geo::mesh::setRecombine(2, parallelogram.surface);
      geo::mesh::setRecombine(2, triangle.surface);
    }
    geo::synchronize();
    // gmsh 4.8's default recombination (Blossom) leaves some triangles in unstructured
    // meshes; "simple full-quad" leaves none. Options are process-wide, so restore it.
    double algorithm = 0;
    gmsh::option::getNumber("Mesh.RecombinationAlgorithm", algorithm);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 2);
    gmsh::model::mesh::generate(2);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", algorithm);
  }

  std::vector<NamedBoundary> names() const {
    return {{"para_flank", 1, {parallelogram.slanted}},
            {"tri_flank", 1, {triangle.slanted}},
            {"para_corner", 0, {parallelogram.corner}},
            {"tri_corner", 0, {triangle.corner}}};
  }

  // Node set sorted along the curve from (x0, y0); edge set with the body on its left.
  static void expect_flank(const Mesh& mesh, const std::string& name, double x0, double y0) {
    const auto& nodes = mesh.node_set(name);
    ASSERT_GE(nodes.size(), 3u);
    double previous = -1;
    for (int n : nodes) {
      const double distance = std::hypot(mesh.nodes(n, 0) - x0, mesh.nodes(n, 1) - y0);
      EXPECT_GT(distance, previous) << name;
      previous = distance;
    }
    EXPECT_EQ(mesh.edge_set(name).size(), nodes.size() - 1);
    expect_body_on_left(mesh, name);
  }

  Body parallelogram{}, triangle{};
};

TEST_F(GmshExtraction, OneMeshPerBody) {
  for (bool recombine : {false, true}) {
    GmshModelScope scope("two_bodies");
    build(recombine);
    const Mesh para = mesh_from_gmsh({parallelogram.surface}, names());
    const Mesh tri = mesh_from_gmsh({triangle.surface}, names());
    const Mesh both = mesh_from_gmsh({}, names());
    const ElementType expected = recombine ? ElementType::Q1 : ElementType::P1;
    EXPECT_EQ(para.element, expected);
    EXPECT_EQ(tri.element, expected);

    for (const Mesh* mesh : {&para, &tri, &both})
      for (double area : cell_areas(*mesh)) EXPECT_GT(area, 0);
    auto total = [](const Mesh& m) {
      const auto areas = cell_areas(m);
      double sum = 0;
      for (double a : areas) sum += a;
      return sum;
    };
    EXPECT_NEAR(total(para), 2.0, 1e-12);
    EXPECT_NEAR(total(tri), 0.75, 1e-12);

    // No node of the other body, and none unused.
    EXPECT_EQ(both.num_nodes(), para.num_nodes() + tri.num_nodes());
    EXPECT_EQ(both.num_cells(), para.num_cells() + tri.num_cells());
    for (const Mesh* mesh : {&para, &tri}) {
      std::vector<bool> used(mesh->num_nodes(), false);
      for (const auto& [a, b] : directed_cell_sides(*mesh)) used[a] = used[b] = true;
      EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
    }

    // Each body keeps only its own named sets.
    EXPECT_EQ(para.node_sets.count("tri_flank"), 0u);
    EXPECT_EQ(para.edge_sets.count("tri_flank"), 0u);
    EXPECT_EQ(para.node_sets.count("tri_corner"), 0u);
    EXPECT_EQ(tri.node_sets.count("para_flank"), 0u);
    ASSERT_EQ(para.node_set("para_corner").size(), 1u);
    EXPECT_EQ(para.nodes(para.node_set("para_corner")[0], 0), 0.0);

    expect_flank(para, "para_flank", 2, 0);  // curve b -> c
    expect_flank(tri, "tri_flank", 5, 0);    // curve f -> g
    expect_flank(both, "para_flank", 2, 0);
    expect_flank(both, "tri_flank", 5, 0);
  }
}

TEST_F(GmshExtraction, NamedPhysicalGroups) {
  GmshModelScope scope("physical_groups");
  build(false);
  const int group = gmsh::model::addPhysicalGroup(1, {parallelogram.slanted});
  gmsh::model::setPhysicalName(1, group, "flank");
  gmsh::model::addPhysicalGroup(1, {triangle.slanted});  // unnamed: ignored
  const auto boundaries = named_physical_groups();
  ASSERT_EQ(boundaries.size(), 1u);
  EXPECT_EQ(boundaries[0].name, "flank");
  EXPECT_EQ(boundaries[0].tags, std::vector<int>{parallelogram.slanted});
  const Mesh mesh = mesh_from_gmsh({parallelogram.surface}, boundaries);
  expect_flank(mesh, "flank", 2, 0);
}

TEST_F(GmshExtraction, ErrorsAreStdExceptions) {
  GmshModelScope scope("errors");
  EXPECT_THROW(mesh_from_gmsh({}, {}), std::runtime_error);  // nothing meshed
  build(false);
  EXPECT_THROW(mesh_from_gmsh({12345}, {}), std::runtime_error);  // no such surface
  EXPECT_THROW(mesh_from_gmsh({}, {{"x", 1, {1}}, {"x", 1, {2}}}), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
