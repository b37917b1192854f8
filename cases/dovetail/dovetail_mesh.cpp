#include "cases/dovetail/dovetail_mesh.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/gmsh_session.h"

namespace thinlayer::dovetail {

namespace {

// Horizontal run of a flank per unit depth, (0.6 − 0.4) / 0.5, written exactly (computing it
// from the corner coordinates would round it to 0.3999999999999999).
constexpr double kFlankSlope = 0.4;
// 1 / cos of the flanks' tilt from the vertical: a flank moved by ε along its normal moves
// by ε·√1.16 horizontally.
const double kFlankSecant = std::sqrt(1 + kFlankSlope * kFlankSlope);


void validate(const MeshOptions& o) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("dovetail mesh: " + what);
  };
  if (!(std::isfinite(o.h_interface) && o.h_interface >= 1e-3 && o.h_interface <= 0.5))
    fail("h_interface must be in [0.001, 0.5] (got " + std::to_string(o.h_interface) + ")");
  if (!(std::isfinite(o.h_far) && o.h_far >= o.h_interface && o.h_far <= 1.0))
    fail("h_far must be in [h_interface, 1] (got " + std::to_string(o.h_far) + ")");
  if (o.layer_elements < 2)
    fail("layer_elements must be >= 2 (got " + std::to_string(o.layer_elements) + ")");
}

struct DovetailTags {
  int s_left = 0, s_bottom = 0, s_right = 0;  // S, head to tail from (−0.4, 0) to (0.4, 0)
  int bottom = 0, top = 0;                    // base y = −1, tenon y = 0.5 (both along +x)
  int base = 0, tenon = 0;                    // surfaces
};

DovetailTags add_geometry() {
  namespace geo = gmsh::model::geo;
  const double w = base_half_width, a = mouth_half_width, b = slot_bottom_half_width;
  const int base_bl = geo::addPoint(-w, -base_depth, 0);
  const int base_br = geo::addPoint(w, -base_depth, 0);
  const int base_tr = geo::addPoint(w, 0, 0);
  const int base_tl = geo::addPoint(-w, 0, 0);
  const int mouth_l = geo::addPoint(-a, 0, 0);
  const int mouth_r = geo::addPoint(a, 0, 0);
  const int corner_l = geo::addPoint(-b, -slot_depth, 0);
  const int corner_r = geo::addPoint(b, -slot_depth, 0);
  const int stem_l = geo::addPoint(-a, stem_height, 0);
  const int stem_r = geo::addPoint(a, stem_height, 0);

  DovetailTags t;
  t.s_left = geo::addLine(mouth_l, corner_l);
  t.s_bottom = geo::addLine(corner_l, corner_r);
  t.s_right = geo::addLine(corner_r, mouth_r);
  t.bottom = geo::addLine(base_bl, base_br);
  const int base_right = geo::addLine(base_br, base_tr);
  const int base_top_r = geo::addLine(base_tr, mouth_r);
  const int base_top_l = geo::addLine(mouth_l, base_tl);
  const int base_left = geo::addLine(base_tl, base_bl);
  const int stem_right = geo::addLine(mouth_r, stem_r);
  t.top = geo::addLine(stem_l, stem_r);
  const int stem_left = geo::addLine(stem_l, mouth_l);

  t.base = geo::addPlaneSurface({geo::addCurveLoop({t.bottom, base_right, base_top_r, -t.s_right,
                                                     -t.s_bottom, -t.s_left, base_top_l,
                                                     base_left})});
  t.tenon = geo::addPlaneSurface(
      {geo::addCurveLoop({t.s_left, t.s_bottom, t.s_right, stem_right, -t.top, stem_left})});
  return t;
}

void set_meshing(const MeshOptions& o, const InterfaceSegments& n, const DovetailTags& t) {
  namespace geo = gmsh::model::geo;
  geo::mesh::setTransfiniteCurve(t.s_left, n.flank + 1);
  geo::mesh::setTransfiniteCurve(t.s_bottom, n.bottom + 1);
  geo::mesh::setTransfiniteCurve(t.s_right, n.flank + 1);
  geo::mesh::setRecombine(2, t.base);
  geo::mesh::setRecombine(2, t.tenon);
  geo::synchronize();

  // Size: h_interface on S, growing linearly with the distance to S up to h_far.
  namespace field = gmsh::model::mesh::field;
  const int distance = field::add("Distance");
  field::setNumbers(distance, "CurvesList",
                    {double(t.s_left), double(t.s_bottom), double(t.s_right)});
  field::setNumber(distance, "NumPointsPerCurve", std::max(100, 4 * n.bottom));
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", o.h_interface);
  field::setNumber(threshold, "SizeMax", o.h_far);
  field::setNumber(threshold, "DistMin", 0);
  field::setNumber(threshold, "DistMax",
                   std::max((o.h_far - o.h_interface) / kSizeGrowthRate, o.h_far));
  field::setAsBackgroundMesh(threshold);
}

std::vector<NamedBoundary> boundaries(const DovetailTags& t) {
  // Curves not on a surface are ignored by mesh_from_gmsh, so one list serves both bodies.
  return {{"S", 1, {t.s_left, t.s_bottom, t.s_right}},
          {"bottom", 1, {t.bottom}},
          {"top", 1, {t.top}}};
}

// Distance from p to the slot face S (the polyline of its three faces).
double distance_to_slot_faces(const Eigen::Vector2d& p) {
  auto segment_distance = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d d = b - a;
    const double s = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - a - s * d).norm();
  };
  const Eigen::Vector2d ml(-mouth_half_width, 0), mr(mouth_half_width, 0);
  const Eigen::Vector2d cl(-slot_bottom_half_width, -slot_depth),
      cr(slot_bottom_half_width, -slot_depth);
  return std::min({segment_distance(ml, cl), segment_distance(cl, cr), segment_distance(cr, mr)});
}

void check_limit_mesh(const Mesh& mesh, const std::string& body, const std::string& end_set,
                      const InterfaceSegments& n) {
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("dovetail mesh: " + body + ": " + what);
  };
  if (mesh.element != ElementType::Q1 || !mesh.triangles.empty())
    fail("gmsh did not produce an all-quad mesh");
  const auto& s = mesh.node_set("S");
  if (static_cast<int>(s.size()) != n.nodes() ||
      static_cast<int>(mesh.edge_set("S").size()) != n.nodes() - 1)
    fail("expected " + std::to_string(n.nodes()) + " nodes on S, got " +
         std::to_string(s.size()));
  for (int node : s)
    if (distance_to_slot_faces(mesh.nodes.row(node).transpose()) > 1e-12)
      fail("a node of S lies off the slot faces");
  mesh.node_set(end_set);
  mesh.edge_set(end_set);
  const MeshQuality q = mesh_quality(mesh);
  if (!(q.min_scaled_jacobian > 0)) fail("gmsh produced a non-convex or degenerate quad");
}

void check_layer_inputs(const LimitMeshes& limit, double eps, int layer_elements) {
  if (!(std::isfinite(eps) && eps > 0 && eps <= thickest_layer))
    throw std::invalid_argument("dovetail layer meshes: eps must be in (0, 0.1] (got " +
                                std::to_string(eps) + ")");
  if (layer_elements < 2)
    throw std::invalid_argument("dovetail layer meshes: layer_elements must be >= 2 (got " +
                                std::to_string(layer_elements) + ")");
  auto has_sets = [](const Mesh& m, const char* end) {
    return m.node_sets.count("S") && m.edge_sets.count("S") && m.node_sets.count(end);
  };
  if (!has_sets(limit.base, "bottom") || !has_sets(limit.tenon, "top"))
    throw std::invalid_argument(
        "dovetail layer meshes: the limit meshes lack the sets S / bottom / top");
  const auto& sb = limit.base.node_set("S");
  const auto& st = limit.tenon.node_set("S");
  if (sb.size() != st.size())
    throw std::invalid_argument("dovetail layer meshes: base and tenon differ in S node count");
  for (std::size_t i = 0; i < sb.size(); ++i)
    if ((limit.base.nodes.row(sb[i]) - limit.tenon.nodes.row(st[i])).norm() > 1e-12)
      throw std::invalid_argument("dovetail layer meshes: base and tenon S nodes " +
                                  std::to_string(i) + " do not coincide");
}

FacePolyline face_positions(const Mesh& mesh, const std::vector<int>& nodes) {
  FacePolyline face(static_cast<Eigen::Index>(nodes.size()), 2);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    face.row(static_cast<Eigen::Index>(i)) = mesh.nodes.row(nodes[i]);
  return face;
}

}  // namespace

double flank_length() { return slot_depth * kFlankSecant; }

double interface_length() { return 2 * flank_length() + 2 * slot_bottom_half_width; }

double slot_half_width(double y) {
  return mouth_half_width - kFlankSlope * y;
}

double offset_half_width(double y, double eps) { return slot_half_width(y) - kFlankSecant * eps; }

double offset_half_width_at_mouth(double eps) { return offset_half_width(0.0, eps); }

Eigen::Vector2d offset_map(const Eigen::Vector2d& point, double eps) {
  const double x = point.x(), y = point.y();
  if (y > 0) return {x * (offset_half_width_at_mouth(eps) / mouth_half_width), y};
  // (1 − 2ε) y, written so that the slot bottom y = −0.5 lands on −0.5 + ε with one rounding.
  const double y_moved = y - 2 * eps * y;
  return {x * (offset_half_width(y_moved, eps) / slot_half_width(y)), y_moved};
}

InterfaceSegments interface_segments(double h_interface) {
  if (!(std::isfinite(h_interface) && h_interface > 0))
    throw std::invalid_argument("dovetail mesh: h_interface must be finite and > 0");
  // Full-quad recombination halves each curve's mesh, so every count must be even.
  auto even_count = [&](double length) {
    return 2 * static_cast<int>(std::max(1L, std::lround(length / (2 * h_interface))));
  };
  return {even_count(flank_length()), even_count(2 * slot_bottom_half_width)};
}

LimitMeshes make_limit_meshes(const MeshOptions& options) {
  validate(options);
  const InterfaceSegments segments = interface_segments(options.h_interface);
  GmshModelScope scope("dovetail");
  LimitMeshes meshes = with_gmsh_errors([&] {
    // "Simple full-quad": always all quads (blossom alone can leave a triangle or two); the
    // quad algorithm 8 is avoided (it crashes this gmsh build).
    ScopedGmshOption recombination("Mesh.RecombinationAlgorithm", 2);
    const DovetailTags tags = add_geometry();
    set_meshing(options, segments, tags);
    gmsh::model::mesh::generate(2);
    LimitMeshes m;
    m.base = mesh_from_gmsh({tags.base}, boundaries(tags));
    m.tenon = mesh_from_gmsh({tags.tenon}, boundaries(tags));
    return m;
  });
  check_limit_mesh(meshes.base, "base", "bottom", segments);
  check_limit_mesh(meshes.tenon, "tenon", "top", segments);
  return meshes;
}

LayerMeshes make_layer_meshes(const LimitMeshes& limit, double eps, int layer_elements) {
  check_layer_inputs(limit, eps, layer_elements);
  LayerMeshes out;
  out.eps = eps;
  out.base = limit.base;
  out.tenon = limit.tenon;
  for (Eigen::Index i = 0; i < out.tenon.nodes.rows(); ++i)
    out.tenon.nodes.row(i) = offset_map(out.tenon.nodes.row(i).transpose(), eps).transpose();
  if (!(mesh_quality(out.tenon).min_scaled_jacobian > 0))
    throw std::runtime_error("dovetail layer meshes: the offset tenon has a non-convex cell at eps = " +
                             std::to_string(eps));
  out.layer = layer_band(face_positions(out.base, out.base.node_set("S")),
                         face_positions(out.tenon, out.tenon.node_set("S")), layer_elements);
  return out;
}

}  // namespace thinlayer::dovetail
