// Dovetail meshes (cases/dovetail/dovetail_mesh.h, SPEC §2.2) and the structured layer band
// they use (core/mesh/layer_band.h).
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cases/dovetail/dovetail_mesh.h"
#include "core/mesh/layer_band.h"
#include "tests/error_message.h"

namespace thinlayer {
namespace {

using Point = Eigen::Vector2d;
using DirectedEdge = std::pair<int, int>;

Point node(const Mesh& mesh, int i) { return mesh.nodes.row(i).transpose(); }

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Signed area of a cell from its diagonals (accurate for very thin cells).
double quad_area(const Mesh& mesh, const std::array<int, 4>& q) {
  return 0.5 * cross(node(mesh, q[2]) - node(mesh, q[0]), node(mesh, q[3]) - node(mesh, q[1]));
}

double total_area(const Mesh& mesh) {
  double area = 0;
  for (const auto& q : mesh.quads) area += quad_area(mesh, q);
  return area;
}

// Each cell side in its cell's order, i.e. with that cell on its left.
std::set<DirectedEdge> directed_cell_sides(const Mesh& mesh) {
  std::set<DirectedEdge> sides;
  for (const auto& q : mesh.quads)
    for (std::size_t k = 0; k < 4; ++k) sides.insert({q[k], q[(k + 1) % 4]});
  return sides;
}

// Every edge of the set is a boundary side with a cell on its left.
void expect_body_on_left(const Mesh& mesh, const std::string& set) {
  const auto sides = directed_cell_sides(mesh);
  for (const auto& [a, b] : mesh.edge_set(set)) {
    EXPECT_TRUE(sides.count({a, b})) << set << ": edge " << a << "->" << b
                                     << " has no cell on its left";
    EXPECT_FALSE(sides.count({b, a})) << set << ": edge " << a << "->" << b
                                      << " is not on the boundary";
  }
}

// The edge set joins consecutive nodes of the node set, each edge once, in order (forward or
// backward along the node set).
void expect_edges_follow_nodes(const Mesh& mesh, const std::string& set, bool forward) {
  const auto& nodes = mesh.node_set(set);
  const auto& edges = mesh.edge_set(set);
  ASSERT_EQ(edges.size() + 1, nodes.size()) << set;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const std::array<int, 2> expected =
        forward ? std::array<int, 2>{nodes[i], nodes[i + 1]}
                : std::array<int, 2>{nodes[i + 1], nodes[i]};
    EXPECT_EQ(edges[i], expected) << set << " edge " << i;
  }
}

// Every corner of every cell is convex and counter-clockwise.
void expect_positive_cells(const Mesh& mesh, const std::string& what) {
  ASSERT_EQ(mesh.element, ElementType::Q1) << what;
  ASSERT_TRUE(mesh.triangles.empty()) << what;
  for (std::size_t c = 0; c < mesh.quads.size(); ++c) {
    const auto& q = mesh.quads[c];
    for (int k = 0; k < 4; ++k) {
      const Point e1 = node(mesh, q[(k + 1) % 4]) - node(mesh, q[k]);
      const Point e2 = node(mesh, q[(k + 3) % 4]) - node(mesh, q[k]);
      ASSERT_GT(cross(e1, e2) / (e1.norm() * e2.norm()), 1e-3)
          << what << ": cell " << c << " corner " << k;
    }
  }
}

// ----------------------------------------------------------------------------------------
// layer_band on a straight band

TEST(LayerBand, StraightBand) {
  // 4 nodes along x on y = 0 (minus) and y = 0.3 (plus), 3 elements across.
  FacePolyline minus(4, 2), plus(4, 2);
  minus << 0, 0, 1, 0, 2, 0, 3, 0;
  plus << 0, 0.3, 1, 0.3, 2, 0.3, 3, 0.3;
  const Mesh band = layer_band(minus, plus, 3);
  EXPECT_EQ(band.element, ElementType::Q1);
  EXPECT_EQ(band.num_nodes(), 4 * 4);
  EXPECT_EQ(band.num_cells(), 3 * 3);
  expect_positive_cells(band, "straight band");
  EXPECT_NEAR(total_area(band), 3 * 0.3, 1e-15);

  const auto& sm = band.node_set("S-");
  const auto& sp = band.node_set("S+");
  ASSERT_EQ(sm.size(), 4u);
  ASSERT_EQ(sp.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(node(band, sm[i]), Point(minus.row(i).transpose())) << i;
    EXPECT_EQ(node(band, sp[i]), Point(plus.row(i).transpose())) << i;
  }
  // Band above the minus face: "S-" runs with the node order, "S+" against it.
  expect_edges_follow_nodes(band, "S-", true);
  expect_edges_follow_nodes(band, "S+", false);
  expect_body_on_left(band, "S-");
  expect_body_on_left(band, "S+");

  const auto& first = band.node_set("end_first");
  const auto& last = band.node_set("end_last");
  ASSERT_EQ(first.size(), 4u);
  ASSERT_EQ(last.size(), 4u);
  for (int j = 0; j <= 3; ++j) {
    EXPECT_NEAR(node(band, first[j]).x(), 0.0, 0.0);
    EXPECT_NEAR(node(band, first[j]).y(), 0.1 * j, 1e-15);
    EXPECT_NEAR(node(band, last[j]).x(), 3.0, 0.0);
    EXPECT_NEAR(node(band, last[j]).y(), 0.1 * j, 1e-15);
  }
  EXPECT_EQ(first.front(), sm.front());
  EXPECT_EQ(first.back(), sp.front());
  EXPECT_EQ(last.front(), sm.back());
  EXPECT_EQ(last.back(), sp.back());

  const MeshQuality q = mesh_quality(band);
  EXPECT_EQ(q.cells, 9);
  EXPECT_NEAR(q.min_angle_deg, 90, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 90, 1e-9);
  EXPECT_NEAR(q.max_aspect_ratio, 10, 1e-9);
  EXPECT_NEAR(q.min_scaled_jacobian, 1, 1e-12);
}

TEST(LayerBand, BandOnTheRightOfTheMinusFace) {
  // Same band, plus face below: cells must still be counter-clockwise, and now "S+" runs
  // with the node order and "S-" against it.
  FacePolyline minus(3, 2), plus(3, 2);
  minus << 0, 0, 1, 0, 2, 0;
  plus << 0, -0.5, 1, -0.5, 2, -0.5;
  const Mesh band = layer_band(minus, plus, 2);
  expect_positive_cells(band, "band below");
  EXPECT_NEAR(total_area(band), 1.0, 1e-15);
  expect_edges_follow_nodes(band, "S-", false);
  expect_edges_follow_nodes(band, "S+", true);
  expect_body_on_left(band, "S-");
  expect_body_on_left(band, "S+");
}

TEST(LayerBand, VeryThinBand) {
  // Thickness 1e-12 relative to a length of order 1, away from the origin.
  for (double t : {1e-8, 1e-10, 1e-12}) {
    FacePolyline minus(5, 2), plus(5, 2);
    for (int i = 0; i < 5; ++i) {
      minus.row(i) << 0.7 + 0.25 * i, -0.3 + 0.1 * i;
      plus.row(i) << 0.7 + 0.25 * i - 0.1 * t, -0.3 + 0.1 * i + t;
    }
    const Mesh band = layer_band(minus, plus, 2);
    EXPECT_EQ(band.num_cells(), 8);
    for (const auto& q : band.quads) EXPECT_GT(quad_area(band, q), 0) << t;
    // Area of the parallelogram band: length × thickness across it, up to the rounding of
    // the input plus face (coordinates of order 1 are off by ~1e-16, which is 1e-4 of t at
    // t = 1e-12).
    const Point along(1.0, 0.4), across(-0.1 * t, t);
    EXPECT_NEAR(total_area(band), cross(along, across), 1e-15 * along.norm()) << t;
    const MeshQuality q = mesh_quality(band);
    EXPECT_GT(q.min_angle_deg, 60);
    EXPECT_GT(q.max_aspect_ratio, 0.1 / t);
  }
}

// layer_band's refusal of a band of two elements between these faces: its message, "" if it took them.
std::string band_refusal(const FacePolyline& minus, const FacePolyline& plus) {
  return message_of<std::invalid_argument>([&] { layer_band(minus, plus, 2); });
}

TEST(LayerBand, Errors) {
  FacePolyline a(3, 2), b(3, 2), c(2, 2), one(1, 2);
  a << 0, 0, 1, 0, 2, 0;
  b << 0, 1, 1, 1, 2, 1;
  c << 0, 1, 1, 1;
  one << 0, 0;
  EXPECT_THROW(layer_band(a, c, 2), std::invalid_argument);      // mismatched sizes
  EXPECT_THROW(layer_band(one, one, 2), std::invalid_argument);  // < 2 nodes
  EXPECT_THROW(layer_band(a, b, 1), std::invalid_argument);      // elements_across < 2
  EXPECT_THROW(layer_band(a, b, 0), std::invalid_argument);
  EXPECT_THROW(layer_band(a, a, 2), std::invalid_argument);      // zero thickness
  FacePolyline nan = b;
  nan(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(layer_band(a, nan, 2), std::invalid_argument);

  // Plus node 2 crosses to the other side of the minus face: the cell between face nodes 1
  // and 2 is inverted, and the message says so.
  FacePolyline crossing = b;
  crossing(2, 1) = -1;
  const std::string crossing_refused = band_refusal(a, crossing);
  EXPECT_NE(crossing_refused.find("face nodes 1 and 2"), std::string::npos) << crossing_refused;
  // Plus face folded back (nodes 1 and 2 swapped): a bow-tie cell between nodes 1 and 2.
  FacePolyline folded = b;
  folded.row(1) = b.row(2);
  folded.row(2) = b.row(1);
  const std::string folded_refused = band_refusal(a, folded);
  EXPECT_NE(folded_refused.find("face nodes"), std::string::npos) << folded_refused;
  // A repeated face node (zero-length segment).
  FacePolyline repeated = a;
  repeated.row(1) = a.row(0);
  EXPECT_THROW(layer_band(repeated, b, 2), std::invalid_argument);

  EXPECT_THROW(mesh_quality(Mesh{}), std::invalid_argument);
}

TEST(MeshQuality, Triangles) {
  Mesh mesh;
  mesh.element = ElementType::P1;
  mesh.nodes.resize(5, 2);
  mesh.nodes << 0, 0, 1, 0, 0.5, std::sqrt(3.0) / 2, 2, 0, 2, 0.5;
  mesh.triangles = {{0, 1, 2}, {1, 3, 4}};  // equilateral; right angle at node 3
  const MeshQuality q = mesh_quality(mesh);
  EXPECT_EQ(q.cells, 2);
  EXPECT_NEAR(q.max_angle_deg, 90, 1e-12);
  EXPECT_NEAR(q.min_angle_deg, std::atan(0.5) * 180 / M_PI, 1e-12);
  EXPECT_NEAR(q.max_aspect_ratio, std::sqrt(1.25) / 0.5, 1e-12);
  EXPECT_NEAR(q.min_scaled_jacobian, 2 / std::sqrt(3.0) * std::sin(std::atan(0.5)), 1e-12);
  mesh.triangles = {{0, 1, 2}};
  EXPECT_NEAR(mesh_quality(mesh).min_scaled_jacobian, 1, 1e-12);
  EXPECT_NEAR(mesh_quality(mesh).min_angle_deg, 60, 1e-12);
}

TEST(MeshQuality, NonConvexQuad) {
  Mesh mesh;
  mesh.nodes.resize(4, 2);
  mesh.nodes << 0, 0, 1, 0, 0.3, 0.3, 0, 1;  // reflex corner at node 2
  mesh.quads = {{0, 1, 2, 3}};
  const MeshQuality q = mesh_quality(mesh);
  EXPECT_GT(q.max_angle_deg, 180);
  EXPECT_LT(q.min_scaled_jacobian, 0);
}

// ----------------------------------------------------------------------------------------
// Dovetail: limit mode

namespace dt = dovetail;

const dt::LimitMeshes& default_limit() {
  static const dt::LimitMeshes meshes = dt::make_limit_meshes();
  return meshes;
}

double slot_area() {
  return 0.5 * (2 * dt::mouth_half_width + 2 * dt::slot_bottom_half_width) * dt::slot_depth;
}

// Runs first (tests run in file order), so gmsh's initialisation is captured too.
// Meshing time is measured by the studies (meshing_time_s), not asserted here: these
// machines are shared and noisy.
TEST(DovetailLimit, MeshingPrintsNothing) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const dt::LimitMeshes meshes = dt::make_limit_meshes();
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
  EXPECT_GT(meshes.base.num_cells(), 0);
}

TEST(DovetailLimit, AllQ1PositiveAndAreas) {
  const auto& m = default_limit();
  expect_positive_cells(m.base, "base");
  expect_positive_cells(m.tenon, "tenon");
  EXPECT_NEAR(total_area(m.base), 2.0 - slot_area(), 1e-12);
  EXPECT_NEAR(total_area(m.tenon), slot_area() + 0.8 * 0.5, 1e-12);
  for (const Mesh* mesh : {&m.base, &m.tenon}) {
    const MeshQuality q = mesh_quality(*mesh);
    EXPECT_GT(q.min_angle_deg, 20);
    EXPECT_LT(q.max_angle_deg, 160);
    EXPECT_LT(q.max_aspect_ratio, 6);
    EXPECT_GT(q.min_scaled_jacobian, 0.3);
  }
}

TEST(DovetailLimit, InterfaceNodesMatch) {
  const auto& m = default_limit();
  const auto& sb = m.base.node_set("S");
  const auto& st = m.tenon.node_set("S");
  std::printf("[dovetail] nodes on S at h_interface = 0.025: %zu (base), %zu (tenon)\n",
              sb.size(), st.size());
  ASSERT_EQ(sb.size(), st.size());
  EXPECT_EQ(sb.size(), 93u);
  EXPECT_EQ(static_cast<int>(sb.size()), dt::interface_segments(0.025).nodes());
  for (std::size_t i = 0; i < sb.size(); ++i)
    EXPECT_LE((node(m.base, sb[i]) - node(m.tenon, st[i])).norm(), 1e-14) << i;
}

TEST(DovetailLimit, InterfaceOrdering) {
  const auto& m = default_limit();
  const auto& s = m.base.node_set("S");
  ASSERT_GE(s.size(), 3u);
  EXPECT_LE((node(m.base, s.front()) - Point(-0.4, 0)).norm(), 1e-15);
  EXPECT_LE((node(m.base, s.back()) - Point(0.4, 0)).norm(), 1e-15);
  const auto segments = dt::interface_segments(0.025);
  ASSERT_EQ(segments.flank, 22);
  ASSERT_EQ(segments.bottom, 48);
  // Both bottom corners, at the expected positions along the node set.
  EXPECT_LE((node(m.base, s[segments.flank]) - Point(-0.6, -0.5)).norm(), 1e-15);
  EXPECT_LE((node(m.base, s[segments.flank + segments.bottom]) - Point(0.6, -0.5)).norm(), 1e-15);
  // Monotone arc length, uniform spacing on each face, total = |S|.
  double arc = 0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const double step = (node(m.base, s[i + 1]) - node(m.base, s[i])).norm();
    EXPECT_GT(step, 0) << i;
    const bool on_bottom = static_cast<int>(i) >= segments.flank &&
                           static_cast<int>(i) < segments.flank + segments.bottom;
    const double expected = on_bottom ? 1.2 / segments.bottom : dt::flank_length() / segments.flank;
    EXPECT_NEAR(step, expected, 1e-12) << i;
    arc += step;
  }
  EXPECT_NEAR(arc, dt::interface_length(), 1e-12);
  // Each node on its face.
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Point p = node(m.base, s[i]);
    const int k = static_cast<int>(i);
    if (k <= segments.flank) {
      EXPECT_NEAR(p.x(), -dt::slot_half_width(p.y()), 1e-15) << i;
    } else if (k < segments.flank + segments.bottom) {
      EXPECT_EQ(p.y(), -0.5) << i;
    } else {
      EXPECT_NEAR(p.x(), dt::slot_half_width(p.y()), 1e-15) << i;
    }
  }
}

TEST(DovetailLimit, EdgeSetsAndBoundaries) {
  const auto& m = default_limit();
  expect_body_on_left(m.base, "S");
  expect_body_on_left(m.tenon, "S");
  expect_body_on_left(m.base, "bottom");
  expect_body_on_left(m.tenon, "top");
  // Base on the right of S's direction, tenon on its left.
  expect_edges_follow_nodes(m.base, "S", false);
  expect_edges_follow_nodes(m.tenon, "S", true);
  for (int i : m.tenon.node_set("top")) EXPECT_EQ(m.tenon.nodes(i, 1), 0.5);
  for (int i : m.base.node_set("bottom")) EXPECT_EQ(m.base.nodes(i, 1), -1.0);
  const auto& top = m.tenon.node_set("top");
  const auto& bottom = m.base.node_set("bottom");
  EXPECT_EQ(node(m.tenon, top.front()), Point(-0.4, 0.5));
  EXPECT_EQ(node(m.tenon, top.back()), Point(0.4, 0.5));
  EXPECT_EQ(node(m.base, bottom.front()), Point(-1, -1));
  EXPECT_EQ(node(m.base, bottom.back()), Point(1, -1));
  EXPECT_FALSE(m.base.node_sets.count("top"));
  EXPECT_FALSE(m.tenon.node_sets.count("bottom"));
}

TEST(DovetailLimit, InterfaceNodeCountsAtOtherSizes) {
  for (double h : {0.05, 0.0125}) {
    dt::MeshOptions options;
    options.h_interface = h;
    const dt::LimitMeshes m = dt::make_limit_meshes(options);
    const auto segments = dt::interface_segments(h);
    EXPECT_EQ(static_cast<int>(m.base.node_set("S").size()), segments.nodes());
    EXPECT_EQ(m.base.node_set("S").size(), m.tenon.node_set("S").size());
    expect_positive_cells(m.base, "base");
    expect_positive_cells(m.tenon, "tenon");
    EXPECT_NEAR(total_area(m.base), 2.0 - slot_area(), 1e-12);
    EXPECT_NEAR(total_area(m.tenon), slot_area() + 0.4, 1e-12);
    std::printf("[dovetail] h_interface = %g: %d + %d + %d segments, %d nodes on S; "
                "base %d Q1, tenon %d Q1\n",
                h, segments.flank, segments.bottom, segments.flank, segments.nodes(),
                m.base.num_cells(), m.tenon.num_cells());
  }
  EXPECT_EQ(dt::interface_segments(0.05).nodes(), 45);
  EXPECT_EQ(dt::interface_segments(0.0125).nodes(), 185);
}

TEST(DovetailLimit, RestoresGmshOptions) {
  default_limit();  // gmsh initialised
  double before = -1, after = -1;
  gmsh::option::getNumber("Mesh.RecombinationAlgorithm", before);
  dt::make_limit_meshes();
  gmsh::option::getNumber("Mesh.RecombinationAlgorithm", after);
  EXPECT_EQ(before, after);
}

TEST(DovetailLimit, ExtremeSizes) {
  for (auto [h, h_far] : {std::pair{0.5, 0.5}, std::pair{0.5, 1.0}, std::pair{0.2, 1.0},
                          std::pair{0.1, 0.1}, std::pair{0.03, 0.03}, std::pair{0.008, 0.1}}) {
    dt::MeshOptions options;
    options.h_interface = h;
    options.h_far = h_far;
    const dt::LimitMeshes m = dt::make_limit_meshes(options);
    EXPECT_EQ(static_cast<int>(m.base.node_set("S").size()), dt::interface_segments(h).nodes());
    expect_positive_cells(m.base, "base");
    expect_positive_cells(m.tenon, "tenon");
    EXPECT_NEAR(total_area(m.base), 2.0 - slot_area(), 1e-12) << h << " " << h_far;
    EXPECT_NEAR(total_area(m.tenon), slot_area() + 0.4, 1e-12) << h << " " << h_far;
  }
}

TEST(DovetailLimit, BadOptions) {
  dt::MeshOptions o;
  o.h_interface = 0;
  EXPECT_THROW(dt::make_limit_meshes(o), std::invalid_argument);
  o = {};
  o.h_interface = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(dt::make_limit_meshes(o), std::invalid_argument);
  o = {};
  o.h_far = 0.01;  // < h_interface
  EXPECT_THROW(dt::make_limit_meshes(o), std::invalid_argument);
  o = {};
  o.layer_elements = 1;
  EXPECT_THROW(dt::make_limit_meshes(o), std::invalid_argument);
}

// ----------------------------------------------------------------------------------------
// Dovetail: layer mode

const std::vector<double> kEps = {1e-2, 1e-3, 1e-4, 1e-8};

// Distance from p to the line through a and b (not the segment).
double line_distance(const Point& p, const Point& a, const Point& b) {
  const Point d = (b - a).normalized();
  return std::abs(cross(d, p - a));
}

TEST(DovetailLayer, TenonKeepsTopologyAndSets) {
  const auto& limit = default_limit();
  for (double eps : kEps) {
    const dt::LayerMeshes m = dt::make_layer_meshes(limit, eps, 2);
    EXPECT_EQ(m.eps, eps);
    EXPECT_EQ(m.tenon.num_nodes(), limit.tenon.num_nodes());
    EXPECT_EQ(m.tenon.quads, limit.tenon.quads) << eps;
    EXPECT_EQ(m.tenon.node_sets, limit.tenon.node_sets) << eps;
    EXPECT_EQ(m.tenon.edge_sets, limit.tenon.edge_sets) << eps;
    // The base is untouched.
    EXPECT_EQ(m.base.nodes, limit.base.nodes);
    EXPECT_EQ(m.base.quads, limit.base.quads);
    expect_positive_cells(m.tenon, "tenon");
    // Stem as wide as the offset trapezoid's top edge; top edge still at y = 0.5.
    double xmin = 1e9, xmax = -1e9;
    for (int i : m.tenon.node_set("top")) {
      EXPECT_EQ(m.tenon.nodes(i, 1), 0.5);
      xmin = std::min(xmin, m.tenon.nodes(i, 0));
      xmax = std::max(xmax, m.tenon.nodes(i, 0));
    }
    EXPECT_NEAR(xmax - xmin, 2 * dt::offset_half_width_at_mouth(eps), 1e-15) << eps;
    EXPECT_NEAR(dt::offset_half_width_at_mouth(eps), 0.4 - std::sqrt(1.16) * eps, 1e-16);
    for (Eigen::Index i = 0; i < m.tenon.nodes.rows(); ++i) {
      if (m.tenon.nodes(i, 1) < 0) continue;
      EXPECT_LE(std::abs(m.tenon.nodes(i, 0)), dt::offset_half_width_at_mouth(eps) + 1e-15);
    }
    // Tenon area: offset trapezoid + narrower stem.
    const double top = dt::offset_half_width_at_mouth(eps);
    const double bottom = dt::offset_half_width(-0.5 + eps, eps);
    const double expected = (top + bottom) * (0.5 - eps) + 2 * top * 0.5;
    EXPECT_NEAR(total_area(m.tenon), expected, 1e-12) << eps;
  }
}

TEST(DovetailLayer, TenonInterfaceOnOffsetFaces) {
  const auto& limit = default_limit();
  const auto segments = dt::interface_segments(0.025);
  const Point ml(-0.4, 0), cl(-0.6, -0.5), cr(0.6, -0.5), mr(0.4, 0);
  for (double eps : kEps) {
    const dt::LayerMeshes m = dt::make_layer_meshes(limit, eps, 2);
    const auto& s = m.tenon.node_set("S");
    double worst = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Point p = node(m.tenon, s[i]);
      const int k = static_cast<int>(i);
      double d;
      if (k == segments.flank || k == segments.flank + segments.bottom) continue;  // corners
      if (k < segments.flank) {
        d = line_distance(p, ml, cl);
      } else if (k < segments.flank + segments.bottom) {
        d = line_distance(p, cl, cr);
      } else {
        d = line_distance(p, cr, mr);
      }
      worst = std::max(worst, std::abs(d - eps));
    }
    // Absolute in units of L: positions are doubles of order 1, so |d − ε| cannot beat a
    // few ulp(0.5) ≈ 1e-16 whatever ε.
    EXPECT_LE(worst, 1e-14) << eps;
    // The bottom corners on the offset corners, at distance eps from both faces.
    const Point left = node(m.tenon, s[segments.flank]);
    const Point right = node(m.tenon, s[segments.flank + segments.bottom]);
    const double cx = dt::offset_half_width(-0.5 + eps, eps);
    EXPECT_LE((left - Point(-cx, -0.5 + eps)).norm(), 1e-15) << eps;
    EXPECT_LE((right - Point(cx, -0.5 + eps)).norm(), 1e-15) << eps;
    EXPECT_NEAR(line_distance(left, ml, cl), eps, 1e-14);
    EXPECT_NEAR(line_distance(right, cr, mr), eps, 1e-14);
    // Mouth corners on y = 0 at the offset half-width.
    EXPECT_EQ(node(m.tenon, s.front()).y(), 0.0);
    EXPECT_NEAR(node(m.tenon, s.front()).x(), -dt::offset_half_width_at_mouth(eps), 1e-15);
    EXPECT_NEAR(node(m.tenon, s.back()).x(), dt::offset_half_width_at_mouth(eps), 1e-15);
    std::printf("[dovetail] eps = %g: max | distance(tenon S node, base face) - eps | = %.2e\n",
                eps, worst);
  }
}

TEST(DovetailLayer, LayerMatchesBothFaces) {
  const auto& limit = default_limit();
  for (double eps : kEps) {
    for (int across : {2, 3}) {
      const dt::LayerMeshes m = dt::make_layer_meshes(limit, eps, across);
      const auto& sb = m.base.node_set("S");
      const auto& st = m.tenon.node_set("S");
      const auto& lm = m.layer.node_set("S-");
      const auto& lp = m.layer.node_set("S+");
      ASSERT_EQ(lm.size(), sb.size());
      ASSERT_EQ(lp.size(), st.size());
      for (std::size_t i = 0; i < sb.size(); ++i) {
        EXPECT_EQ(node(m.layer, lm[i]), node(m.base, sb[i])) << i;
        EXPECT_EQ(node(m.layer, lp[i]), node(m.tenon, st[i])) << i;
      }
      EXPECT_EQ(m.layer.num_cells(), static_cast<int>(sb.size() - 1) * across);
      EXPECT_EQ(m.layer.node_set("end_first").size(), static_cast<std::size_t>(across + 1));
      // Band on the left of S's direction: "S-" with the node order, "S+" against it; both
      // opposite to the adherent they face.
      expect_edges_follow_nodes(m.layer, "S-", true);
      expect_edges_follow_nodes(m.layer, "S+", false);
      expect_body_on_left(m.layer, "S-");
      expect_body_on_left(m.layer, "S+");
      for (const auto& q : m.layer.quads) ASSERT_GT(quad_area(m.layer, q), 0) << eps;
    }
  }
}

TEST(DovetailLayer, LayerAreaIsEpsTimesS) {
  // The band fills the slot minus the offset trapezoid exactly, so its area is
  //   0.5 − (0.5 − ε)(1 − (0.4 + 2√1.16) ε) = ε|S| − (0.4 + 2√1.16) ε²,  |S| = 1.2 + √1.16:
  // first order ε|S|, with a second-order deficit ≈ 2.55 ε² from the corners.
  const auto& limit = default_limit();
  const double length = dt::interface_length();
  const double k2 = 0.4 + 2 * std::sqrt(1.16);
  for (double eps : kEps) {
    const dt::LayerMeshes m = dt::make_layer_meshes(limit, eps, 2);
    const double area = total_area(m.layer);
    const double first_order = eps * length;
    // First order: relative deviation bounded by the second-order term (k2 ε / |S| ≈ 1.1 ε).
    EXPECT_NEAR(area / first_order, 1.0, 1.2 * k2 * eps / length + 1e-6) << eps;
    // Exact: up to round-off in node positions of order 1 (≈ 1e-16 each, relative to ε).
    EXPECT_NEAR(area, first_order - k2 * eps * eps, 1e-13 * length) << eps;
    std::printf("[dovetail] eps = %g: layer area / (eps |S|) = %.12f (exact %.12f)\n", eps,
                area / first_order, 1 - k2 * eps / length);
  }
}

TEST(DovetailLayer, Quality) {
  const auto& limit = default_limit();
  double previous_aspect = 0;
  for (double eps : kEps) {
    const dt::LayerMeshes m = dt::make_layer_meshes(limit, eps, 2);
    const MeshQuality layer = mesh_quality(m.layer);
    const MeshQuality tenon = mesh_quality(m.tenon);
    EXPECT_TRUE(std::isfinite(layer.min_angle_deg) && std::isfinite(layer.max_angle_deg) &&
                std::isfinite(layer.max_aspect_ratio) && std::isfinite(layer.min_scaled_jacobian));
    EXPECT_EQ(layer.cells, m.layer.num_cells());
    EXPECT_GT(layer.min_angle_deg, 20);
    EXPECT_LT(layer.max_angle_deg, 160);
    EXPECT_GT(layer.min_scaled_jacobian, 0.3);
    // Aspect ratio ~ (segment length) / (ε / layer_elements): like 1/ε.
    EXPECT_GT(layer.max_aspect_ratio, 0.5 * 0.0245 * 2 / eps) << eps;
    EXPECT_LT(layer.max_aspect_ratio, 2.0 * 0.0245 * 2 / eps) << eps;
    EXPECT_GT(layer.max_aspect_ratio, previous_aspect);
    previous_aspect = layer.max_aspect_ratio;
    EXPECT_GT(tenon.min_scaled_jacobian, 0.3);
    std::printf("[dovetail] eps = %g layer: %d cells, angles %.2f..%.2f deg, max aspect %.4g, "
                "min scaled Jacobian %.4f; tenon: angles %.2f..%.2f, aspect %.3g\n",
                eps, layer.cells, layer.min_angle_deg, layer.max_angle_deg,
                layer.max_aspect_ratio, layer.min_scaled_jacobian, tenon.min_angle_deg,
                tenon.max_angle_deg, tenon.max_aspect_ratio);
  }
}

TEST(DovetailLayer, OffsetMapIsContinuous) {
  for (double eps : kEps) {
    const Point above = dt::offset_map(Point(0.3, 1e-300), eps);
    const Point at = dt::offset_map(Point(0.3, 0.0), eps);
    EXPECT_NEAR((above - at).norm(), 0.0, 1e-15);
    // The slot faces map onto the offset faces.
    for (double y : {-0.5, -0.37, -0.1, 0.0}) {
      const Point p = dt::offset_map(Point(-dt::slot_half_width(y), y), eps);
      EXPECT_NEAR(p.x(), -dt::offset_half_width(p.y(), eps), 1e-15);
    }
  }
}

TEST(DovetailLayer, BadArguments) {
  const auto& limit = default_limit();
  EXPECT_THROW(dt::make_layer_meshes(limit, 0.0, 2), std::invalid_argument);
  EXPECT_THROW(dt::make_layer_meshes(limit, -1e-3, 2), std::invalid_argument);
  EXPECT_THROW(dt::make_layer_meshes(limit, std::numeric_limits<double>::quiet_NaN(), 2),
               std::invalid_argument);
  EXPECT_THROW(dt::make_layer_meshes(limit, 0.5, 2), std::invalid_argument);
  EXPECT_THROW(dt::make_layer_meshes(limit, 1e-3, 1), std::invalid_argument);
  dt::LimitMeshes broken = limit;
  broken.tenon.node_sets.erase("S");
  EXPECT_THROW(dt::make_layer_meshes(broken, 1e-3, 2), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
