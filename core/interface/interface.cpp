#include "core/interface/interface.h"

#include <map>
#include <stdexcept>

namespace thinlayer {

namespace {

struct NodeGeometry {
  Eigen::Vector2d normal_sum = Eigen::Vector2d::Zero();
  double length = 0;
};

// Normal sum and tributary length of every node touched by the edges. The edges have the
// body on their left, so the body's outward normal of edge a→b is (s_y, -s_x)/|s|; the
// interface normal points into the plus body, i.e. against it.
std::map<int, NodeGeometry> edge_geometry(const Mesh& mesh, const std::vector<std::array<int, 2>>& edges) {
  std::map<int, NodeGeometry> geometry;
  for (const auto& [a, b] : edges) {
    const Eigen::Vector2d s = (mesh.nodes.row(b) - mesh.nodes.row(a)).transpose();
    const double h = s.norm();
    if (!(h > 0)) throw std::runtime_error("interface: zero-length edge");
    const Eigen::Vector2d into_body(-s.y() / h, s.x() / h);
    for (int node : {a, b}) {
      geometry[node].normal_sum += into_body;
      geometry[node].length += 0.5 * h;
    }
  }
  return geometry;
}

InterfaceNode make_node(const Model& model, int plus_body, int node, const std::map<int, NodeGeometry>& geometry) {
  const Mesh& mesh = model.bodies.at(plus_body).mesh;
  auto it = geometry.find(node);
  if (it == geometry.end()) throw std::runtime_error("interface: node " + std::to_string(node) + " is on none of the interface edges");
  InterfaceNode n;
  n.plus_body = plus_body;
  n.plus_node = node;
  n.plus_dof_x = model.dof_offset(plus_body) + 2 * node;
  n.x = mesh.nodes.row(node).transpose();
  n.normal = it->second.normal_sum.normalized();
  n.length = it->second.length;
  return n;
}

}  // namespace

Interface foundation_interface(const std::string& name, const InterfaceLaw& law, const Model& model,
                               int plus_body, const std::vector<int>& nodes,
                               const std::vector<std::array<int, 2>>& edges) {
  const Mesh& mesh = model.bodies.at(plus_body).mesh;
  const auto geometry = edge_geometry(mesh, edges);
  Interface interface{name, law, {}};
  for (int node : nodes) interface.nodes.push_back(make_node(model, plus_body, node, geometry));
  return interface;
}

Interface paired_interface(const std::string& name, const InterfaceLaw& law, const Model& model,
                           int plus_body, const std::vector<int>& plus_nodes,
                           const std::vector<std::array<int, 2>>& plus_edges, int minus_body,
                           const std::vector<int>& minus_nodes, double tolerance) {
  const Mesh& plus = model.bodies.at(plus_body).mesh;
  const Mesh& minus = model.bodies.at(minus_body).mesh;
  const auto geometry = edge_geometry(plus, plus_edges);
  Interface interface{name, law, {}};
  for (int node : plus_nodes) {
    InterfaceNode n = make_node(model, plus_body, node, geometry);
    double best = tolerance;
    for (int m : minus_nodes) {
      const double d = (minus.nodes.row(m).transpose() - n.x).norm();
      if (d <= best) {
        best = d;
        n.minus_node = m;
      }
    }
    if (n.minus_node < 0)
      throw std::runtime_error("interface '" + name + "': no matching node on the minus side at (" +
                               std::to_string(n.x.x()) + ", " + std::to_string(n.x.y()) + ")");
    n.minus_body = minus_body;
    n.minus_dof_x = model.dof_offset(minus_body) + 2 * n.minus_node;
    interface.nodes.push_back(n);
  }
  return interface;
}

}  // namespace thinlayer
