#include "core/mesh/mesh_bytes.h"

#include <stdexcept>

namespace thinlayer {

namespace {

// A Mesh read back refers only to its own nodes: the meshing child that sent it ran gmsh on a
// user's files, and the reader must not index past the node table whatever it received.
void check_indices(const Mesh& m) {
  const long long n = m.nodes.rows();
  auto check = [n](int node) {
    if (node < 0 || node >= n) throw std::runtime_error("bytes: a mesh refers to node " + std::to_string(node) + " of " + std::to_string(n));
  };
  if (m.element != ElementType::Q1 && m.element != ElementType::P1) throw std::runtime_error("bytes: a mesh of no element type");
  for (const auto& q : m.quads)
    for (int k : q) check(k);
  for (const auto& t : m.triangles)
    for (int k : t) check(k);
  for (const auto& [name, nodes] : m.node_sets)
    for (int k : nodes) check(k);
  for (const auto& [name, edges] : m.edge_sets)
    for (const auto& e : edges) check(e[0]), check(e[1]);
}

}  // namespace

void put(ByteWriter& w, const Mesh& m) {
  put(w, m.element), put(w, m.nodes), put(w, m.quads), put(w, m.triangles);
  put(w, m.node_sets), put(w, m.edge_sets);
}

void get(ByteReader& r, Mesh& m) {
  get(r, m.element), get(r, m.nodes), get(r, m.quads), get(r, m.triangles);
  get(r, m.node_sets), get(r, m.edge_sets);
  check_indices(m);
}

}  // namespace thinlayer
