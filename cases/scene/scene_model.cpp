#include "cases/scene/scene_model.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "cases/layer_quadrature.h"
#include "cases/scene/scene_morph.h"

namespace thinlayer {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Why a plus body's cells cannot follow the offset of its bondline.
constexpr const char* kCannotFollow =
    "its cells there cannot follow the offset: the body is too thin there, or the bondline has a corner (each side's "
    "nodal normal moves by eps, so an acute corner limits eps to about half the element size), or a free face must "
    "step by eps where the bondline ends; a plus body that can move away as a whole (the outer strips of a lap) holds "
    "any layer";

[[noreturn]] void fail_at(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

// Nodes "at the same position" across the interface: round-off of coordinates of the model's
// size (gmsh writes both bodies' nodes of a shared curve from the same points).
double match_tolerance(const SceneMeshes& m) { return 1e-9 * m.size; }

std::string point_text(const Eigen::Vector2d& x) {
  std::ostringstream s;
  s << "(" << x.x() << ", " << x.y() << ")";
  return s.str();
}
std::string point_text(const Mesh& m, int node) { return point_text(Eigen::Vector2d(m.nodes.row(node).transpose())); }

std::string mm(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// The bondline's nodes on the plus body, ordered along its edges from one end to the other.
std::vector<int> chain(const SceneInterfaceSpec& i, const Mesh& plus) {
  const auto& edges = plus.edge_set(i.group);
  std::map<int, std::vector<int>> next;
  for (const auto& [a, b] : edges) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  std::vector<int> ends;
  for (const auto& [node, around] : next) {
    if (around.size() > 2) fail_at(i.group_where, "interface group '" + i.group + "' branches at " + point_text(plus, node));
    if (around.size() == 1) ends.push_back(node);
  }
  if (ends.size() != 2)
    fail_at(i.group_where, "interface group '" + i.group + "' must be one open curve (it is closed or in pieces)");
  std::vector<int> order = {std::min(ends[0], ends[1])};
  int previous = -1;
  while (order.size() < next.size()) {
    const auto& around = next[order.back()];
    const int step = around[0] != previous ? around[0] : around.size() > 1 ? around[1] : -1;
    if (step < 0) break;
    previous = order.back();
    order.push_back(step);
  }
  if (order.size() != next.size()) fail_at(i.group_where, "interface group '" + i.group + "' is in pieces");
  return order;
}

bool holds(const SceneSpec& spec, const Mesh& m) {
  for (const SceneSupportSpec& s : spec.supports)
    if (m.node_sets.count(s.group)) return true;
  return false;
}

std::vector<Body> scene_bodies(const SceneSpec& spec, const std::vector<Mesh>& meshes) {
  std::vector<Body> bodies;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    Body body{spec.bodies[b].name, meshes[b], Material{spec.bodies[b].lambda, spec.bodies[b].mu, spec.plane}};
    body.floating = !holds(spec, meshes[b]);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

// Outward unit normal of a boundary edge a → b (the body on its left).
Eigen::Vector2d outward(const Mesh& m, const std::array<int, 2>& e) {
  const Eigen::Vector2d s = (m.nodes.row(e[1]) - m.nodes.row(e[0])).transpose();
  return Eigen::Vector2d(s.y(), -s.x()) / s.norm();
}

double edge_length(const Mesh& m, const std::array<int, 2>& e) { return (m.nodes.row(e[1]) - m.nodes.row(e[0])).norm(); }

// One load on the model's bodies (the adherents only: its group may touch several).
void add_load(const SceneLoadSpec& l, int adherents, Model& model) {
  auto on_curve = [&](int b) { return model.bodies[b].mesh.edge_sets.count(l.group) > 0; };
  bool curve = false;
  double length = 0;  // the whole curve's, over every body it touches (mm)
  for (int b = 0; b < adherents; ++b)
    if (on_curve(b)) {
      curve = true;
      for (const auto& e : model.bodies[b].mesh.edge_set(l.group)) length += edge_length(model.bodies[b].mesh, e);
    }
  const Eigen::Vector2d vector(l.vector[0], l.vector[1]);
  if (!curve) {  // a force on a physical point: shared equally by its nodes (one, normally)
    std::vector<std::pair<int, int>> nodes;
    for (int b = 0; b < adherents && nodes.empty(); ++b)
      if (model.bodies[b].mesh.node_sets.count(l.group))
        for (int n : model.bodies[b].mesh.node_set(l.group)) nodes.push_back({b, n});
    for (const auto& [b, n] : nodes) model.nodal_forces.push_back({l.group, b, n, vector / nodes.size()});
    return;
  }
  for (int b = 0; b < adherents; ++b) {
    if (!on_curve(b)) continue;
    const Mesh& m = model.bodies[b].mesh;
    const auto& edges = m.edge_set(l.group);
    if (l.kind == LoadKind::Traction) model.tractions.push_back({l.group, b, edges, vector});
    if (l.kind == LoadKind::Force) model.tractions.push_back({l.group, b, edges, vector / length});  // spread uniformly
    if (l.kind == LoadKind::Pressure)  // normal to each edge, pushing into the body
      for (const auto& e : edges) model.tractions.push_back({l.group, b, {e}, -l.pressure * outward(m, e)});
  }
}

// Supports and loads on every adherent their group touches; the reaction of a support is named
// after its group.
void add_supports_and_loads(const SceneSpec& spec, Model& model) {
  const int adherents = static_cast<int>(spec.bodies.size());
  for (const SceneSupportSpec& s : spec.supports)
    for (int b = 0; b < adherents; ++b) {
      const Mesh& m = model.bodies[b].mesh;
      if (!m.node_sets.count(s.group)) continue;
      for (int c = 0; c < 2; ++c)
        if (s.u[c]) model.dirichlet.push_back({s.group, b, m.node_set(s.group), c, *s.u[c]});
    }
  for (const SceneLoadSpec& l : spec.loads) add_load(l, adherents, model);
}

FacePolyline positions(const Mesh& m, const std::vector<int>& nodes) {
  FacePolyline face(static_cast<Eigen::Index>(nodes.size()), 2);
  for (std::size_t k = 0; k < nodes.size(); ++k) face.row(static_cast<Eigen::Index>(k)) = m.nodes.row(nodes[k]);
  return face;
}

SceneInterfaceNodes match_bondline(const SceneInterfaceSpec& i, const Mesh& plus, const Mesh& minus, double tolerance) {
  for (const auto& [body, mesh] : {std::pair{i.plus, &plus}, std::pair{i.minus, &minus}})
    if (!mesh->edge_sets.count(i.group))
      fail_at(i.group_where, "interface group '" + i.group + "' is not shared by its bodies: it is not on the boundary of body '" +
                                 body + "'");
  SceneInterfaceNodes S;
  S.plus = chain(i, plus);
  const auto& candidates = minus.node_set(i.group);
  for (int node : S.plus) {
    int best = -1;
    double best_d = tolerance;
    for (int m : candidates) {
      const double d = (minus.nodes.row(m) - plus.nodes.row(node)).norm();
      if (d <= best_d) best_d = d, best = m;
    }
    if (best < 0)
      fail_at(i.group_where, "interface group '" + i.group + "' is not shared by its bodies: body '" + i.minus +
                                 "' has no node at " + point_text(plus, node) + " of body '" + i.plus + "'");
    S.minus.push_back(best);
  }
  if (candidates.size() != S.plus.size() || minus.edge_set(i.group).size() != plus.edge_set(i.group).size())
    fail_at(i.group_where, "interface group '" + i.group + "' is not shared by its bodies: their meshes differ along it");
  return S;
}

// Every group of bodies joined by bondlines needs a support somewhere (else it floats free).
void check_held(const SceneSpec& spec, const SceneMeshes& meshes) {
  const int n = static_cast<int>(spec.bodies.size());
  std::vector<int> group(n);
  for (int b = 0; b < n; ++b) group[b] = b;
  std::function<int(int)> root = [&](int b) { return group[b] == b ? b : group[b] = root(group[b]); };
  std::vector<bool> bonded(n, false);
  for (const SceneInterfaceSpec& i : spec.interfaces) {
    const int p = spec.body_index(i.plus), m = spec.body_index(i.minus);
    bonded[p] = bonded[m] = true;
    group[root(p)] = root(m);
  }
  for (int b = 0; b < n; ++b)
    if (!bonded[b] && !holds(spec, meshes.bodies[b]))
      fail_at(spec.bodies[b].where, "body '" + spec.bodies[b].name + "' has no support and no contact: nothing holds it");
  std::set<int> held;
  for (int b = 0; b < n; ++b)
    if (holds(spec, meshes.bodies[b])) held.insert(root(b));
  for (const SceneInterfaceSpec& i : spec.interfaces)
    if (!held.count(root(spec.body_index(i.plus))))
      fail_at(i.where, spec.interface_list ? "no body joined to " + i.label() + " has a support: nothing holds them"
                                           : "neither body of the interface has a support: nothing holds the assembly");
}

// The bondline's length (mm): the sum of its nodes' tributary lengths.
double bondline_length(const Interface& S) {
  double length = 0;
  for (const InterfaceNode& n : S.nodes) length += n.length;
  return length;
}

// The smallest cosine allowed between a make_room direction and a bondline's normal: beyond 78°
// from the normal the layer's columns would lie nearly along the bondline (its cells' angles under 12°).
constexpr double kRoomCosine = 0.2;

// How far and where a plus body's bondline node moves per unit of layer thickness: along the normal
// n (by 1), or along the scene's make_room direction d by 1 / (d·n), so that the layer is ε thick
// across the bondline (its columns then run along d).
Eigen::Vector2d room_step(const SceneInterfaceSpec& i, const InterfaceNode& node) {
  if (!i.make_room) return node.normal;
  const Eigen::Vector2d d((*i.make_room)[0], (*i.make_room)[1]);
  const double c = d.dot(node.normal);
  if (c < kRoomCosine) {
    std::ostringstream s;
    s << i.make_room_where << ": 'make_room' [" << d.x() << ", " << d.y() << "] is "
      << std::acos(std::clamp(c, -1.0, 1.0)) * 180 / 3.141592653589793 << " deg from " << i.label()
      << "'s normal at " << point_text(node.x)
      << " (at most 78 deg, pointing from the minus body into the plus body: the layer's cells would be too flat)";
    throw InputError(s.str());
  }
  return d / c;
}

// The offsets that make room for layers of the given thicknesses (per bondline, 0: none): each
// plus body's bondline nodes by t n (or along the bondline's make_room direction, room_step), its
// nodes on any other bondline held. A node given two
// different offsets (two bondlines meeting on it) is refused.
std::vector<NodeOffsets> layer_offsets(const SceneSpec& spec, const std::vector<Interface>& limit,
                                       const std::vector<double>& thickness, const std::vector<Mesh>& meshes) {
  std::vector<NodeOffsets> offsets(spec.bodies.size());
  std::vector<std::map<int, std::string>> owner(spec.bodies.size());
  auto impose = [&](int body, int node, const Eigen::Vector2d& d, const std::string& bondline) {
    auto [it, fresh] = offsets[body].try_emplace(node, d);
    if (!fresh && (it->second - d).norm() > 1e-12 * (1 + d.norm()))
      throw std::invalid_argument("bondlines '" + owner[body][node] + "' and '" + bondline + "' meet at " +
                                  point_text(meshes[body], node) + " of body '" + spec.bodies[body].name +
                                  "': the layer mode cannot give that node two offsets (keep the bondlines apart, or make them one curve)");
    owner[body].try_emplace(node, bondline);
  };
  const std::size_t n = spec.interfaces.size();
  std::set<int> moving;  // the plus bodies of layers
  for (std::size_t i = 0; i < n; ++i)
    if (thickness[i] > 0) moving.insert(limit[i].nodes.front().plus_body);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& group = spec.interfaces[i].group;
    for (const InterfaceNode& node : limit[i].nodes) {
      if (moving.count(node.plus_body))
        impose(node.plus_body, node.plus_node, thickness[i] * room_step(spec.interfaces[i], node), group);
      if (moving.count(node.minus_body)) impose(node.minus_body, node.minus_node, Eigen::Vector2d::Zero(), group);
    }
  }
  return offsets;
}

std::vector<std::string> body_names(const SceneSpec& spec) {
  std::vector<std::string> names;
  for (const SceneBodySpec& b : spec.bodies) names.push_back(b.name);
  return names;
}

std::vector<Interface> limit_interfaces(const SceneSpec& spec, const SceneMeshes& meshes,
                                        const std::vector<SceneInterfaceNodes>& S) {
  const Model model = make_scene_limit_model(spec, meshes);
  std::vector<Interface> out;
  for (std::size_t i = 0; i < spec.interfaces.size(); ++i)
    out.push_back(make_scene_limit_interface(spec, model, static_cast<int>(i), S[i], InterfaceLaw{}));
  return out;
}

}  // namespace

std::vector<SceneInterfaceNodes> check_scene_meshes(const SceneSpec& spec, const SceneMeshes& meshes) {
  std::vector<SceneInterfaceNodes> out;
  for (const SceneInterfaceSpec& i : spec.interfaces)
    out.push_back(match_bondline(i, meshes.bodies.at(spec.body_index(i.plus)), meshes.bodies.at(spec.body_index(i.minus)),
                                 match_tolerance(meshes)));
  check_held(spec, meshes);
  for (const SceneSupportSpec& s : spec.supports) {
    bool touches = false;
    for (const Mesh& m : meshes.bodies) touches = touches || m.node_sets.count(s.group);
    if (!touches) fail_at(s.where, "support group '" + s.group + "' touches none of the bodies");
  }
  for (const SceneLoadSpec& l : spec.loads) {
    bool touches = false;
    for (const Mesh& m : meshes.bodies)
      touches = touches || m.edge_sets.count(l.group) || (l.kind == LoadKind::Force && m.node_sets.count(l.group));
    if (!touches) fail_at(l.where, "load group '" + l.group + "' lies on the boundary of none of the bodies");
  }
  return out;
}

std::string interface_name(const SceneSpec& spec, int i, const std::string& face) {
  return spec.interface_list ? spec.interfaces.at(i).group + "/" + face : face;
}

Model make_scene_limit_model(const SceneSpec& spec, const SceneMeshes& meshes) {
  Model model;
  model.bodies = scene_bodies(spec, meshes.bodies);
  add_supports_and_loads(spec, model);
  return model;
}

Interface make_scene_limit_interface(const SceneSpec& spec, const Model& model, int i, const SceneInterfaceNodes& S,
                                     const InterfaceLaw& law) {
  const SceneInterfaceSpec& b = spec.interfaces.at(i);
  const int plus = spec.body_index(b.plus), minus = spec.body_index(b.minus);
  Interface interface = paired_interface(interface_name(spec, i, "S"), law, model, plus, S.plus,
                                         model.bodies[plus].mesh.edge_set(b.group), minus, S.minus, inf);
  // Pair by the order found in check_scene_meshes (already matched by position), not by
  // paired_interface's nearest search, which the infinite tolerance above leaves free.
  for (std::size_t k = 0; k < S.minus.size(); ++k) {
    interface.nodes[k].minus_node = S.minus[k];
    interface.nodes[k].minus_dof_x = model.dof_offset(minus) + 2 * S.minus[k];
  }
  return interface;
}

double layer_thickness(const SceneInterfaceSpec& i, double eps) {
  if (!i.has_layer_mode()) return 0.0;
  if (eps > 0) return eps;
  if (i.glue) return i.glue->thickness;
  throw std::invalid_argument(i.label() + " gives the paper's family ('layer'): the layer mode needs a thickness (--eps)");
}

InterfaceLaw scene_given_law(const SceneInterfaceSpec& i) {
  if (!i.lambda_bar || !i.mu_bar) throw std::invalid_argument(i.label() + " gives no limit law ('law')");
  return layer_limit_law(*i.lambda_bar, *i.mu_bar, i.faces, i.friction);
}

ThickestLayer scene_thickest_layer(const SceneSpec& spec, const SceneMeshes& meshes,
                                   const std::vector<SceneInterfaceNodes>& S) {
  ThickestLayer out;
  if (!spec.has_layer() || spec.element != ElementType::Q1) return out;
  const std::vector<Interface> limit = limit_interfaces(spec, meshes, S);
  std::vector<double> unit(spec.interfaces.size(), 0.0);
  out.eps = inf;
  for (std::size_t i = 0; i < spec.interfaces.size(); ++i) {
    if (!spec.interfaces[i].has_layer_mode()) continue;
    unit[i] = 1.0;
    const double tenth = bondline_length(limit[i]) / 10;
    if (tenth < out.eps) {
      out.eps = tenth;
      out.reason = "a tenth of the length of " + spec.interfaces[i].label() + ", " + mm(10 * tenth) +
                   " mm (a thicker layer is no longer thin)";
    }
  }
  const Morph morph = morph_bodies(meshes.bodies, body_names(spec), layer_offsets(spec, limit, unit, meshes.bodies));
  if (morph.inversion_scale / 2 < out.eps) {
    out.eps = morph.inversion_scale / 2;
    out.reason = "half the thickness, " + mm(morph.inversion_scale) + " mm, at which making room for the layer would invert a cell of body '" +
                 morph.inverting_body + "' near " + point_text(morph.inverting_cell_centre) + " (" + kCannotFollow + ")";
  }
  return out;
}

SceneLayerModel make_scene_layer_model(const SceneSpec& spec, const SceneMeshes& meshes,
                                       const std::vector<SceneInterfaceNodes>& S, double eps) {
  if (!spec.has_layer()) throw std::invalid_argument("the scene gives limit laws ('law') only: it has no layer mode");
  if (spec.element != ElementType::Q1) throw std::invalid_argument("layer mode needs a Q1 scene (its band is Q1)");
  if (eps < 0 || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  const std::size_t n = spec.interfaces.size();
  const std::vector<Interface> limit = limit_interfaces(spec, meshes, S);
  SceneLayerModel out;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = layer_thickness(spec.interfaces[i], eps);
    const double tenth = bondline_length(limit[i]) / 10;
    if (t > tenth)
      throw std::invalid_argument("a layer of " + mm(t) + " mm is too thick for " + spec.interfaces[i].label() + ": at most " +
                                  mm(tenth) + " mm, a tenth of its length " + mm(10 * tenth) +
                                  " mm (a thicker layer is no longer thin)");
    out.thickness.push_back(t);
  }
  const Morph morph = morph_bodies(meshes.bodies, body_names(spec), layer_offsets(spec, limit, out.thickness, meshes.bodies));
  if (morph.inversion_scale < 2) {
    std::ostringstream s;
    s << "the layer is too thick for this joint: making room for it would invert a cell of body '" << morph.inverting_body
      << "' near " << point_text(morph.inverting_cell_centre) << " at " << morph.inversion_scale
      << " times its thickness; at most " << morph.inversion_scale / 2 << " times it (" << kCannotFollow << ")";
    throw std::invalid_argument(s.str());
  }

  out.model.bodies = scene_bodies(spec, morph.meshes);
  const double tol = match_tolerance(meshes);
  for (std::size_t i = 0; i < n; ++i) {
    const SceneInterfaceSpec& b = spec.interfaces[i];
    out.layer_body.push_back(-1);
    out.layer_quality.push_back({});
    out.moduli.push_back({});
    if (!b.has_layer_mode()) continue;
    const int plus = spec.body_index(b.plus), minus = spec.body_index(b.minus);
    const Glue glue = b.glue_model();
    out.moduli.back() = glue.at(out.thickness[i]);
    const Mesh band = layer_band(positions(meshes.bodies[minus], S[i].minus), positions(morph.meshes[plus], S[i].plus),
                                 spec.layer_elements);
    out.layer_quality.back() = mesh_quality(band);
    Body layer{spec.interface_list ? "layer-" + b.group : "layer", band,
               Material{out.moduli.back().lambda, out.moduli.back().mu, spec.plane}};
    layer.floating = true;
    // A nearly incompressible layer (γ < δ: λ_ε/μ_ε grows like 1/ε) locks with full integration,
    // unless its zigzag mode is free under the selective rule (γ < 1 and γ < δ): the rule of
    // cases/layer_quadrature.h, as for the dovetail. Selective integration is plane strain only.
    layer.selective_integration =
        spec.plane == PlaneHypothesis::Strain && selective_layer_quadrature(glue.gamma(), glue.delta());
    out.model.bodies.push_back(std::move(layer));
    out.layer_body.back() = static_cast<int>(out.model.bodies.size()) - 1;
  }
  add_supports_and_loads(spec, out.model);

  for (std::size_t i = 0; i < n; ++i) {
    const SceneInterfaceSpec& b = spec.interfaces[i];
    const int plus = spec.body_index(b.plus), minus = spec.body_index(b.minus);
    if (out.layer_body[i] < 0) {  // a law only: the bondline as in limit mode, on the moved meshes
      out.interfaces.push_back(make_scene_limit_interface(spec, out.model, static_cast<int>(i), S[i], scene_given_law(b)));
      continue;
    }
    const int layer = out.layer_body[i];
    const Mesh& lb = out.model.bodies[layer].mesh;
    out.interfaces.push_back(paired_interface(interface_name(spec, static_cast<int>(i), "S+"), face_law(b.faces.plus, b.friction),
                                              out.model, plus, S[i].plus, out.model.bodies[plus].mesh.edge_set(b.group), layer,
                                              lb.node_set("S+"), tol));
    out.interfaces.push_back(paired_interface(interface_name(spec, static_cast<int>(i), "S-"), face_law(b.faces.minus, b.friction),
                                              out.model, layer, lb.node_set("S-"), lb.edge_set("S-"), minus, S[i].minus, tol));
  }
  return out;
}

std::map<std::string, Eigen::Vector2d> applied_load_resultants(const Model& model) {
  std::map<std::string, Eigen::Vector2d> out;
  for (const EdgeTraction& t : model.tractions) {
    auto [it, _] = out.try_emplace(t.name, Eigen::Vector2d::Zero());
    for (const auto& e : t.edges) it->second += edge_length(model.bodies[t.body].mesh, e) * t.traction;
  }
  for (const NodalForce& f : model.nodal_forces) {
    auto [it, _] = out.try_emplace(f.name, Eigen::Vector2d::Zero());
    it->second += f.force;
  }
  return out;
}

}  // namespace thinlayer
