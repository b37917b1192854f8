#include "cases/bar/bar.h"

#include <stdexcept>

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

  const Mesh& mesh = bar.mesh;
  Model model;
  model.dirichlet.push_back({"DE", 0, mesh.node_set("right"), 0, 0.0});
  model.dirichlet.push_back({"D", 0, mesh.node_set("bottom_right"), 1, 0.0});
  model.dirichlet.push_back({"D", 0, mesh.node_set("bottom_right"), 0, 0.0});  // already owned by DE
  model.tractions.push_back({"AG", 0, mesh.edge_set("left"), {F1, 0.0}});
  model.tractions.push_back({"GE", 0, mesh.edge_set("top"), {0.0, F2}});
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

}  // namespace thinlayer::bar
