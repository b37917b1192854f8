#include "cases/scene/scene_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace thinlayer {

namespace {

// Area (mm²) and the boundary's length (mm) of a cell list: an edge used by one cell only is on
// the boundary.
template <std::size_t N>
void add_cells(const Mesh& m, const std::vector<std::array<int, N>>& cells, double& area,
               std::map<std::pair<int, int>, int>& edge_uses) {
  for (const auto& c : cells)
    for (std::size_t a = 0; a < N; ++a) {
      const int i = c[a], j = c[(a + 1) % N];
      area += 0.5 * (m.nodes(i, 0) * m.nodes(j, 1) - m.nodes(j, 0) * m.nodes(i, 1));  // shoelace, counter-clockwise
      ++edge_uses[{std::min(i, j), std::max(i, j)}];
    }
}

}  // namespace

double mesh_thickness(const Mesh& m) {
  double area = 0;
  std::map<std::pair<int, int>, int> uses;
  add_cells(m, m.quads, area, uses);
  add_cells(m, m.triangles, area, uses);
  double perimeter = 0;
  for (const auto& [edge, count] : uses)
    if (count == 1) perimeter += (m.nodes.row(edge.first) - m.nodes.row(edge.second)).norm();
  return perimeter > 0 ? 2 * area / perimeter : 0.0;
}

double scene_characteristic_length(const SceneSpec& spec, const std::vector<Mesh>& meshes) {
  if (spec.characteristic_length) return *spec.characteristic_length;
  double L = std::numeric_limits<double>::infinity();
  for (const SceneInterfaceSpec& i : spec.interfaces)
    for (const std::string& body : {i.plus, i.minus}) L = std::min(L, mesh_thickness(meshes.at(spec.body_index(body))));
  return L;
}

AdherentData bondline_reference(const SceneSpec& spec, int i, double L) {
  const SceneBodySpec& plus = spec.bodies.at(spec.body_index(spec.interfaces.at(i).plus));
  const SceneBodySpec& minus = spec.bodies.at(spec.body_index(spec.interfaces.at(i).minus));
  AdherentData ref;
  ref.mu_m = std::min(plus.mu, minus.mu);
  ref.lambda_m = std::min(plus.lambda, minus.lambda);
  if (!(ref.lambda_m > 0)) ref.lambda_m = ref.mu_m;
  ref.L = L;
  return ref;
}

}  // namespace thinlayer
