#include "cases/scene/scene_model.h"

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "cases/layer_quadrature.h"

namespace thinlayer {

namespace {

[[noreturn]] void fail_at(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

// Nodes "at the same position" across the interface: round-off of coordinates of the model's
// size (gmsh writes both bodies' nodes of a shared curve from the same points).
double match_tolerance(const SceneMeshes& m) { return 1e-9 * m.size; }

std::string point_text(const Mesh& m, int node) {
  std::ostringstream s;
  s << "(" << m.nodes(node, 0) << ", " << m.nodes(node, 1) << ")";
  return s.str();
}

// The interface's nodes on the plus body, ordered along its edges from one end to the other.
std::vector<int> chain(const SceneSpec& spec, const Mesh& plus) {
  const auto& edges = plus.edge_set(spec.interface.group);
  std::map<int, std::vector<int>> next;
  for (const auto& [a, b] : edges) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  std::vector<int> ends;
  for (const auto& [node, around] : next) {
    if (around.size() > 2) fail_at(spec.interface.group_where, "interface group '" + spec.interface.group + "' branches at " + point_text(plus, node));
    if (around.size() == 1) ends.push_back(node);
  }
  if (ends.size() != 2)
    fail_at(spec.interface.group_where, "interface group '" + spec.interface.group +
                                            "' must be one open curve (it is closed or in pieces)");
  std::vector<int> order = {std::min(ends[0], ends[1])};
  int previous = -1;
  while (order.size() < next.size()) {
    const auto& around = next[order.back()];
    const int step = around[0] != previous ? around[0] : around.size() > 1 ? around[1] : -1;
    if (step < 0) break;
    previous = order.back();
    order.push_back(step);
  }
  if (order.size() != next.size())
    fail_at(spec.interface.group_where, "interface group '" + spec.interface.group + "' is in pieces");
  return order;
}

bool holds(const SceneSpec& spec, const Mesh& m) {
  for (const SceneSupportSpec& s : spec.supports)
    if (m.node_sets.count(s.group)) return true;
  return false;
}

std::vector<Body> scene_bodies(const SceneSpec& spec, const SceneMeshes& meshes) {
  std::vector<Body> bodies;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    Body body{spec.bodies[b].name, meshes.bodies[b], Material{spec.bodies[b].lambda, spec.bodies[b].mu, spec.plane}};
    body.floating = !holds(spec, meshes.bodies[b]);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

// Supports and loads on every body their group touches; the reaction of a support is named
// after its group.
void add_supports_and_loads(const SceneSpec& spec, Model& model) {
  for (const SceneSupportSpec& s : spec.supports)
    for (int b = 0; b < static_cast<int>(spec.bodies.size()); ++b) {
      const Mesh& m = model.bodies[b].mesh;
      if (!m.node_sets.count(s.group)) continue;
      for (int c = 0; c < 2; ++c)
        if (s.u[c]) model.dirichlet.push_back({s.group, b, m.node_set(s.group), c, *s.u[c]});
    }
  for (const SceneLoadSpec& l : spec.loads)
    for (int b = 0; b < static_cast<int>(spec.bodies.size()); ++b) {
      const Mesh& m = model.bodies[b].mesh;
      if (m.edge_sets.count(l.group))
        model.tractions.push_back({l.group, b, m.edge_set(l.group), Eigen::Vector2d(l.traction[0], l.traction[1])});
    }
}

FacePolyline positions(const Mesh& m, const std::vector<int>& nodes) {
  FacePolyline face(static_cast<Eigen::Index>(nodes.size()), 2);
  for (std::size_t k = 0; k < nodes.size(); ++k) face.row(static_cast<Eigen::Index>(k)) = m.nodes.row(nodes[k]);
  return face;
}

}  // namespace

SceneInterfaceNodes check_scene_meshes(const SceneSpec& spec, const SceneMeshes& meshes) {
  const SceneInterfaceSpec& i = spec.interface;
  const Mesh& plus = meshes.bodies.at(spec.body_index(i.plus));
  const Mesh& minus = meshes.bodies.at(spec.body_index(i.minus));
  for (const auto& [body, mesh] : {std::pair{i.plus, &plus}, std::pair{i.minus, &minus}})
    if (!mesh->edge_sets.count(i.group))
      fail_at(i.group_where, "interface group '" + i.group + "' is not shared by its bodies: it is not on the boundary of body '" +
                                 body + "'");
  SceneInterfaceNodes S;
  S.plus = chain(spec, plus);
  const auto& candidates = minus.node_set(i.group);
  for (int node : S.plus) {
    int best = -1;
    double best_d = match_tolerance(meshes);
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

  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    const std::string& name = spec.bodies[b].name;
    if (name != i.plus && name != i.minus && !holds(spec, meshes.bodies[b]))
      fail_at(spec.bodies[b].where, "body '" + name + "' has no support and no contact: nothing holds it");
  }
  if (!holds(spec, plus) && !holds(spec, minus))
    fail_at(i.where, "neither body of the interface has a support: nothing holds the assembly");
  for (const SceneSupportSpec& s : spec.supports) {
    bool touches = false;
    for (const Mesh& m : meshes.bodies) touches = touches || m.node_sets.count(s.group);
    if (!touches) fail_at(s.where, "support group '" + s.group + "' touches none of the bodies");
  }
  for (const SceneLoadSpec& l : spec.loads) {
    bool touches = false;
    for (const Mesh& m : meshes.bodies) touches = touches || m.edge_sets.count(l.group);
    if (!touches) fail_at(l.where, "load group '" + l.group + "' lies on the boundary of none of the bodies");
  }
  return S;
}

Model make_scene_limit_model(const SceneSpec& spec, const SceneMeshes& meshes) {
  Model model;
  model.bodies = scene_bodies(spec, meshes);
  add_supports_and_loads(spec, model);
  return model;
}

Interface make_scene_limit_interface(const SceneSpec& spec, const Model& model, const SceneInterfaceNodes& S,
                                     const InterfaceLaw& law) {
  const int plus = spec.body_index(spec.interface.plus), minus = spec.body_index(spec.interface.minus);
  Interface interface = paired_interface("S", law, model, plus, S.plus,
                                         model.bodies[plus].mesh.edge_set(spec.interface.group), minus, S.minus,
                                         std::numeric_limits<double>::infinity());
  // Pair by the order found in check_scene_meshes (already matched by position), not by
  // paired_interface's nearest search, which the infinite tolerance above leaves free.
  for (std::size_t k = 0; k < S.minus.size(); ++k) {
    interface.nodes[k].minus_node = S.minus[k];
    interface.nodes[k].minus_dof_x = model.dof_offset(minus) + 2 * S.minus[k];
  }
  return interface;
}

double scene_thickest_layer(const SceneSpec& spec, const SceneMeshes& meshes, const SceneInterfaceNodes& S) {
  const Model model = make_scene_limit_model(spec, meshes);
  const Interface interface = make_scene_limit_interface(spec, model, S, InterfaceLaw{});
  const Mesh& plus = model.bodies[spec.body_index(spec.interface.plus)].mesh;
  std::map<int, Eigen::Vector2d> normal;
  for (const InterfaceNode& n : interface.nodes) normal[n.plus_node] = n.normal;
  double depth = std::numeric_limits<double>::infinity();
  auto visit = [&](const auto& cell) {
    for (int i : cell) {
      auto it = normal.find(i);
      if (it == normal.end()) continue;
      double d = 0;
      for (int j : cell) d = std::max(d, it->second.dot((plus.nodes.row(j) - plus.nodes.row(i)).transpose()));
      depth = std::min(depth, d);
    }
  };
  for (const auto& q : plus.quads) visit(q);
  for (const auto& t : plus.triangles) visit(t);
  return depth / 2;
}

SceneLayerModel make_scene_layer_model(const SceneSpec& spec, const SceneMeshes& meshes, const SceneInterfaceNodes& S,
                                       double eps) {
  if (!spec.has_layer()) throw std::invalid_argument("the scene gives a limit law ('law'), not a layer: it has no layer mode");
  if (spec.element != ElementType::Q1) throw std::invalid_argument("layer mode needs a Q1 scene (its band is Q1)");
  const double thickest = scene_thickest_layer(spec, meshes, S);
  if (!(eps > 0) || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  if (eps > thickest) {
    std::ostringstream s;
    s << "eps " << eps << " mm is too thick for the elements of body '" << spec.interface.plus
      << "' along the interface: at most " << thickest << " mm (half their depth there)";
    throw std::invalid_argument(s.str());
  }
  const int plus = spec.body_index(spec.interface.plus), minus = spec.body_index(spec.interface.minus);
  const Model limit = make_scene_limit_model(spec, meshes);
  const Interface S0 = make_scene_limit_interface(spec, limit, S, InterfaceLaw{});

  SceneLayerModel out;
  const SceneLayerSpec& glue = *spec.interface.layer;
  out.lambda_eps = std::pow(eps, glue.gamma) * glue.lambda_g;
  out.mu_eps = std::pow(eps, glue.delta) * glue.mu_g;
  out.model.bodies = scene_bodies(spec, meshes);
  Mesh& moved = out.model.bodies[plus].mesh;
  for (const InterfaceNode& n : S0.nodes) moved.nodes.row(n.plus_node) += eps * n.normal.transpose();
  if (!(mesh_quality(moved).min_scaled_jacobian > 0))
    throw std::invalid_argument("eps is too thick for the elements of body '" + spec.interface.plus +
                                "': moving its interface nodes inverts a cell");
  const Mesh band = layer_band(positions(meshes.bodies[minus], S.minus), positions(moved, S.plus), spec.layer_elements);
  out.layer_quality = mesh_quality(band);
  Body layer{"layer", band, Material{out.lambda_eps, out.mu_eps, spec.plane}};
  layer.floating = true;
  // A nearly incompressible layer (γ < δ: λ_ε/μ_ε grows like 1/ε) locks with full integration,
  // unless its zigzag mode is free under the selective rule (γ < 1 and γ < δ): the rule of
  // cases/layer_quadrature.h, as for the dovetail. Selective integration is plane strain only.
  layer.selective_integration = spec.plane == PlaneHypothesis::Strain && selective_layer_quadrature(glue.gamma, glue.delta);
  out.model.bodies.push_back(std::move(layer));
  out.layer_body = static_cast<int>(out.model.bodies.size()) - 1;
  add_supports_and_loads(spec, out.model);

  const InterfaceLaw signorini_coulomb =
      InterfaceLaw::make(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), spec.interface.friction);
  const Mesh& lb = out.model.bodies[out.layer_body].mesh;
  const double tol = match_tolerance(meshes);
  // (`moved` may dangle: the layer's push_back above can reallocate the bodies.)
  out.interfaces.push_back(paired_interface("S+", signorini_coulomb, out.model, plus, S.plus,
                                            out.model.bodies[plus].mesh.edge_set(spec.interface.group), out.layer_body, lb.node_set("S+"), tol));
  out.interfaces.push_back(paired_interface("S-", signorini_coulomb, out.model, out.layer_body, lb.node_set("S-"),
                                            lb.edge_set("S-"), minus, S.minus, tol));
  return out;
}

}  // namespace thinlayer
