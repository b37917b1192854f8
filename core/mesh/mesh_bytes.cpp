#include "core/mesh/mesh_bytes.h"

namespace thinlayer {

void put(ByteWriter& w, const Mesh& m) {
  put(w, m.element), put(w, m.nodes), put(w, m.quads), put(w, m.triangles);
  put(w, m.node_sets), put(w, m.edge_sets);
}

void get(ByteReader& r, Mesh& m) {
  get(r, m.element), get(r, m.nodes), get(r, m.quads), get(r, m.triangles);
  get(r, m.node_sets), get(r, m.edge_sets);
}

}  // namespace thinlayer
