#include "cases/bar/bar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/mesh/distortion.h"
#include "core/mesh/layer_band.h"

namespace thinlayer::bar {

Model make_model(const MeshOptions& options) {
  RectangleMeshSpec spec;
  spec.width = side;
  spec.height = side;
  spec.nx = options.nx;
  spec.ny = options.ny;
  spec.element = options.element;
  spec.diagonal = options.diagonal;
  Body bar{"bar", structured_rectangle(spec), Material{lambda_m, mu_m, options.plane}};
  if (options.distortion != 0) {
    distort_interior(bar.mesh, options.distortion, side / std::max(options.nx, options.ny));
    if (!(mesh_quality(bar.mesh).min_scaled_jacobian > 0))
      throw std::invalid_argument("mesh distortion " + std::to_string(options.distortion) +
                                  " inverts a cell of the bar's mesh (guaranteed valid below 0.25 for Q1, 0.167 for P1)");
  }
  if (!std::isfinite(options.load_scale)) throw std::invalid_argument("bar: the load scale must be finite");

  const Mesh& mesh = bar.mesh;
  Model model;
  model.dirichlet.push_back({"DE", 0, mesh.node_set("right"), 0, 0.0});
  model.dirichlet.push_back({"D", 0, mesh.node_set("bottom_right"), 1, 0.0});
  model.dirichlet.push_back({"D", 0, mesh.node_set("bottom_right"), 0, 0.0});  // already owned by DE
  model.tractions.push_back({"AG", 0, mesh.edge_set("left"), {options.load_scale * F1, 0.0}});
  model.tractions.push_back({"GE", 0, mesh.edge_set("top"), {0.0, options.load_scale * F2}});
  model.bodies.push_back(std::move(bar));
  return model;
}

Interface make_interface(const Model& model, const InterfaceLaw& law) {
  const Mesh& mesh = model.bodies.at(0).mesh;
  std::vector<int> contact_nodes = mesh.node_set("bottom");  // sorted by x: A first, D last
  if (contact_nodes.empty() || contact_nodes.back() != mesh.node_set("bottom_right").at(0))
    throw std::logic_error("bar: node set 'bottom' must end at D");
  contact_nodes.pop_back();  // D is pinned; its reaction is reported separately
  return foundation_interface("S", law, model, 0, contact_nodes, mesh.edge_set("bottom"));
}

Model make_layer_model(const MeshOptions& mesh, const LayerOptions& layer) {
  if (!(layer.eps > 0) || !std::isfinite(layer.eps)) throw std::invalid_argument("eps must be finite and > 0");
  Model model = make_model(mesh);
  const Mesh& bar = model.bodies[0].mesh;
  // The layer's faces: its top face matches AD node for node, its bottom face lies eps below.
  const std::vector<int>& ad = bar.node_set("bottom");
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> top(ad.size(), 2), bottom(ad.size(), 2);
  for (size_t i = 0; i < ad.size(); ++i) {
    top.row(i) = bar.nodes.row(ad[i]);
    bottom.row(i) << bar.nodes(ad[i], 0), -layer.eps;
  }
  // Fully integrated Q1 (see the dovetail's layer for the selective rule; here the full rule
  // is the one with which every Table 3 row converges).
  Body body{"layer", layer_band(bottom, top, layer.layer_elements),
            Material{layer.lambda_eps, layer.mu_eps, mesh.plane}, true};
  model.bodies.push_back(std::move(body));
  return model;
}

std::vector<Interface> make_layer_interfaces(const Model& model) {
  const InterfaceLaw signorini_coulomb = InterfaceLaw::make(std::numeric_limits<double>::infinity(),
                                                            std::numeric_limits<double>::infinity(), friction);
  const Mesh& bar = model.bodies.at(0).mesh;
  const Mesh& layer = model.bodies.at(1).mesh;
  std::vector<int> bar_nodes = bar.node_set("bottom");
  std::vector<int> top = layer.node_set("S+"), bottom = layer.node_set("S-");
  // D is pinned and not a contact node (SPEC §2.1.1), so the layer's top face skips the node
  // under D; its bottom face rests on the foundation everywhere, the node under D included
  // (without it the layer's end would hang by the layer's in-plane stiffness alone).
  bar_nodes.pop_back();
  top.pop_back();
  Interface upper = paired_interface("S+", signorini_coulomb, model, 0, bar_nodes, bar.edge_set("bottom"), 1, top,
                                     1e-9 * side);
  Interface lower = foundation_interface("S-", signorini_coulomb, model, 1, bottom, layer.edge_set("S-"));
  return {upper, lower};
}

}  // namespace thinlayer::bar
