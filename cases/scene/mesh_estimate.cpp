#include "cases/scene/mesh_estimate.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/mesh/gmsh_session.h"
#include "core/mesh/meshing_child.h"

namespace thinlayer {

namespace {

// Nodes per h² of area (see the header; calibrated on the lap joint and the scene tests' strips).
double nodes_per_area(ElementType element) { return element == ElementType::Q1 ? 2.5 : 1.2; }

std::vector<int> entities(int dim, const std::string& name) {
  std::vector<int> tags;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  for (const auto& [d, tag] : groups) {
    std::string n;
    gmsh::model::getPhysicalName(d, tag, n);
    if (n != name) continue;
    std::vector<int> e;
    gmsh::model::getEntitiesForPhysicalGroup(d, tag, e);
    tags.insert(tags.end(), e.begin(), e.end());
  }
  return tags;
}

// 64 points along the curve (|tag|), reversed for a negative tag.
std::vector<std::array<double, 2>> samples(int tag) {
  std::vector<double> lo, hi, xyz;
  gmsh::model::getParametrizationBounds(1, std::abs(tag), lo, hi);
  std::vector<double> t;
  for (int k = 0; k <= 64; ++k) t.push_back(lo.at(0) + (hi.at(0) - lo.at(0)) * k / 64.0);
  gmsh::model::getValue(1, std::abs(tag), t, xyz);
  std::vector<std::array<double, 2>> p;
  for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) p.push_back({xyz[k], xyz[k + 1]});
  if (tag < 0) std::reverse(p.begin(), p.end());
  return p;
}

double length(int tag) {
  const auto p = samples(tag);
  double l = 0;
  for (std::size_t k = 1; k < p.size(); ++k) l += std::hypot(p[k][0] - p[k - 1][0], p[k][1] - p[k - 1][1]);
  return l;
}

// The oriented boundary curves of a body's surfaces.
std::vector<int> boundary(const std::vector<int>& surfaces) {
  std::vector<int> curves;
  for (int s : surfaces) {
    gmsh::vectorpair out;
    gmsh::model::getBoundary({{2, s}}, out, /*combined=*/false, /*oriented=*/true, /*recursive=*/false);
    for (const auto& [dim, tag] : out)
      if (dim == 1) curves.push_back(tag);
  }
  return curves;
}

// The area the oriented boundary encloses (holes, oriented the other way, count negative).
double area(const std::vector<int>& surfaces) {
  double twice = 0;
  for (int s : surfaces) {
    double surface = 0;
    gmsh::vectorpair out;
    gmsh::model::getBoundary({{2, s}}, out, false, true, false);
    for (const auto& [dim, tag] : out) {
      const auto p = samples(tag);
      for (std::size_t k = 1; k < p.size(); ++k) surface += p[k - 1][0] * p[k][1] - p[k][0] * p[k - 1][1];
    }
    twice += std::abs(surface);
  }
  return twice / 2;
}

double option(const std::string& name) {
  double v = 0;
  gmsh::option::getNumber(name, v);
  return v;
}

// The .geo's own clipping of every size, in gmsh 4.8's order (Mesh/BackgroundMeshTools.cpp,
// BGM_MeshSize): clamped to [MeshSizeMin, MeshSizeMax] (the larger wins), then scaled by
// MeshSizeFactor.
double clipped(double h) {
  return std::min(std::max(h, option("Mesh.MeshSizeMin")), option("Mesh.MeshSizeMax")) * option("Mesh.MeshSizeFactor");
}

// ∫ dA / h² over a body of area `a` with `l` mm of bondline on its boundary: a band along the
// bondline where h grows from h_i to h_f, and h_f beyond.
double inverse_square_size_integral(double a, double l, double h_i, double h_f) {
  if (l <= 0) return a / (h_f * h_f);
  const double reach = std::max((h_f - h_i) / kSizeGrowthRate, h_f);  // scene_mesh.cpp's DistMax
  const double depth = std::min(reach, a / l);
  const double k = (h_f - h_i) / reach;
  const double band = k > 0 ? l / k * (1 / h_i - 1 / (h_i + k * depth)) : l * depth / (h_i * h_i);
  return band + std::max(0.0, a - l * depth) / (h_f * h_f);
}

double estimate_from_mesh_size(const SceneSpec& spec) {
  std::set<int> on_bondline;
  for (const SceneInterfaceSpec& i : spec.interfaces)
    for (int c : entities(1, i.group)) on_bondline.insert(c);
  const double h_i = clipped(*spec.h_interface), h_f = std::max(h_i, clipped(*spec.h_far));
  std::set<int> in_body;
  double nodes = 0;
  for (const SceneBodySpec& b : spec.bodies) {
    const std::vector<int> surfaces = entities(2, b.group);
    in_body.insert(surfaces.begin(), surfaces.end());
    double l = 0;
    for (int c : boundary(surfaces))
      if (on_bondline.count(std::abs(c))) l += length(c);
    nodes += inverse_square_size_integral(area(surfaces), l, h_i, h_f);
  }
  for (int s : all_surfaces())  // gmsh meshes every surface, one in no body too: at the far size
    if (!in_body.count(s)) nodes += area({s}) / (h_f * h_f);
  return nodes_per_area(spec.element) * nodes;
}

// The .geo's own sizes: mesh the curves (the size floored so that this stays bounded), take
// each surface's mean boundary segment, clear the curve mesh. Transfinite counts ignore sizes:
// refuse_oversized_mesh bounds this pass's memory and time itself.
double estimate_from_curve_mesh(const SceneSpec& spec) {
  const std::vector<int> surfaces = all_surfaces();
  std::map<int, std::vector<int>> curves;
  double total_length = 0;
  for (int s : surfaces) {
    curves[s] = boundary({s});
    for (int c : curves[s]) total_length += length(c);
  }
  // gmsh scales the clamped size by MeshSizeFactor last: the floor is set on the clamp, divided
  // by the factor (a factor of 1e-7 would otherwise go under it), and the ceiling kept above it.
  const double previous_min = option("Mesh.MeshSizeMin"), previous_max = option("Mesh.MeshSizeMax");
  const double factor = option("Mesh.MeshSizeFactor");
  const double floor = total_length / static_cast<double>(spec.max_nodes) / (factor > 0 ? factor : 1.0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", std::max(previous_min, floor));
  gmsh::option::setNumber("Mesh.MeshSizeMax", std::max(previous_max, std::max(previous_min, floor)));
  gmsh::model::mesh::generate(1);
  gmsh::option::setNumber("Mesh.MeshSizeMin", previous_min);
  gmsh::option::setNumber("Mesh.MeshSizeMax", previous_max);
  double nodes = 0;
  for (int s : surfaces) {
    double perimeter = 0, segments = 0;
    for (int c : curves[s]) {
      std::vector<std::size_t> tags;
      std::vector<double> xyz, u;
      gmsh::model::mesh::getNodes(tags, xyz, u, 1, std::abs(c), /*includeBoundary=*/true, false);
      segments += std::max<double>(1, static_cast<double>(tags.size()) - 1);
      perimeter += length(c);
    }
    const double h = perimeter / std::max(segments, 1.0);
    nodes += nodes_per_area(spec.element) * area({s}) / (h * h) + segments;
  }
  gmsh::model::mesh::clear();
  return nodes;
}

double node_count_of_msh() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, u;
  gmsh::model::mesh::getNodes(tags, xyz, u, -1, -1, false, false);
  return static_cast<double>(tags.size());
}

}  // namespace

double estimated_mesh_nodes(const SceneSpec& spec) {
  if (spec.geometry.empty()) return node_count_of_msh();
  return spec.h_interface ? estimate_from_mesh_size(spec) : estimate_from_curve_mesh(spec);
}

void refuse_oversized_mesh(const SceneSpec& spec) {
  double nodes = 0;
  const std::string file = spec.geometry.empty() ? spec.mesh : spec.geometry;
  const unsigned seconds = static_cast<unsigned>(estimate_seconds);  // within the command's clock, which may end it first
  run_bounded("estimating the mesh's size", estimate_memory_bytes, seconds,
              file + ": estimating the mesh's size took more than " + std::to_string(estimate_memory_bytes >> 20) +
                  " MiB or " + std::to_string(seconds) +
                  " s: the geometry asks for a very fine mesh (a Transfinite count, Mesh.MeshSizeFactor, "
                  "Mesh.MeshSizeMin?); coarsen it or give mesh_size",
              [&] { nodes = estimated_mesh_nodes(spec); });
  if (!(nodes <= static_cast<double>(spec.max_nodes))) {
    std::ostringstream s;
    s.precision(2);
    s << spec.geometry_where << ": the mesh would have about " << nodes << " nodes, above the limit of "
      << spec.max_nodes << " (--max-nodes): "
      << (spec.geometry.empty() ? "give a coarser mesh" : spec.h_interface ? "raise mesh_size" : "raise the .geo's sizes")
      << " or the limit";
    throw InputError(s.str());
  }
}

}  // namespace thinlayer
