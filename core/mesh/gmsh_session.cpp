#include "core/mesh/gmsh_session.h"

#include <gmsh.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include <unistd.h>

namespace thinlayer {

namespace {

// gmsh element type codes (gmsh::model::mesh::getElementProperties).
constexpr int kGmshLine2 = 1;
constexpr int kGmshTriangle3 = 2;
constexpr int kGmshQuadrangle4 = 3;

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Lives from the first use of gmsh to the end of the process, so gmsh is initialised once.
class GmshRuntime {
 public:
  GmshRuntime() {
    // The user's gmshrc / gmsh-options could change meshing defaults from one machine to
    // the next, so they are not read.
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    // Meshing must not write to the terminal: the CLI's stdout is parsed, and tests
    // check it. Errors still reach us as exceptions (initialize sets AbortOnError = 2).
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
  }
  ~GmshRuntime() {
    try {
      gmsh::finalize();
    } catch (...) {  // nothing sensible to do at exit
    }
  }
  GmshRuntime(const GmshRuntime&) = delete;
  GmshRuntime& operator=(const GmshRuntime&) = delete;
};

using NodeIndex = std::unordered_map<std::size_t, int>;  // gmsh node tag -> Mesh node

// The 2D cells of the selected surfaces, as gmsh node tags.
struct GmshCells {
  ElementType element = ElementType::Q1;
  int nodes_per_cell = 0;
  std::vector<std::size_t> node_tags;  // nodes_per_cell tags per cell, concatenated
};

ElementType element_type_of(int gmsh_type, int surface) {
  if (gmsh_type == kGmshQuadrangle4) return ElementType::Q1;
  if (gmsh_type == kGmshTriangle3) return ElementType::P1;
  throw std::runtime_error("gmsh surface " + std::to_string(surface) +
                           " has elements of gmsh type " + std::to_string(gmsh_type) +
                           "; only linear triangles or quadrangles are supported");
}

GmshCells collect_cells(const std::vector<int>& surfaces) {
  GmshCells cells;
  for (int surface : surfaces) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, surface);
    for (std::size_t k = 0; k < types.size(); ++k) {
      const ElementType element = element_type_of(types[k], surface);
      if (cells.nodes_per_cell != 0 && element != cells.element)
        throw std::runtime_error(
            "gmsh mesh mixes triangles and quadrangles (partly recombined?); a Mesh holds one "
            "element type");
      cells.element = element;
      cells.nodes_per_cell = element == ElementType::Q1 ? 4 : 3;
      cells.node_tags.insert(cells.node_tags.end(), node_tags[k].begin(), node_tags[k].end());
    }
  }
  if (cells.node_tags.empty())
    throw std::runtime_error(
        "gmsh model has no 2D cells on the selected surfaces "
        "(was the mesh generated?)");
  return cells;
}

// Numbers the nodes used by the cells 0..N-1 in increasing gmsh tag order, which drops the
// nodes of other surfaces and of curves or points not attached to any cell.
NodeIndex number_used_nodes(const std::vector<std::size_t>& cell_node_tags) {
  std::vector<std::size_t> tags = cell_node_tags;
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  NodeIndex index;
  for (std::size_t i = 0; i < tags.size(); ++i) index.emplace(tags[i], static_cast<int>(i));
  return index;
}

void fill_coordinates(const NodeIndex& index, Mesh& mesh) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, /*includeBoundary=*/false,
                              /*returnParametricCoord=*/false);
  mesh.nodes.resize(static_cast<Eigen::Index>(index.size()), 2);
  std::size_t filled = 0;
  for (std::size_t k = 0; k < tags.size(); ++k) {
    auto it = index.find(tags[k]);
    if (it == index.end()) continue;
    mesh.nodes(it->second, 0) = xyz[3 * k];
    mesh.nodes(it->second, 1) = xyz[3 * k + 1];
    ++filled;
  }
  if (filled != index.size())
    throw std::runtime_error("gmsh returned cells referring to unknown nodes");
}

template <std::size_t N>
double signed_area(const Mesh& mesh, const std::array<int, N>& cell) {
  double twice_area = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const int a = cell[k], b = cell[(k + 1) % N];
    twice_area += mesh.nodes(a, 0) * mesh.nodes(b, 1) - mesh.nodes(b, 0) * mesh.nodes(a, 1);
  }
  return 0.5 * twice_area;
}

// gmsh orients cells after the surface's normal, which may point along -z.
template <std::size_t N>
std::array<int, N> counter_clockwise(const Mesh& mesh, std::array<int, N> cell) {
  const double area = signed_area(mesh, cell);
  if (area == 0) throw std::runtime_error("gmsh mesh has a cell of zero area");
  if (area < 0) std::reverse(cell.begin() + 1, cell.end());
  return cell;
}

template <std::size_t N>
std::vector<std::array<int, N>> convert_cells(const GmshCells& cells, const NodeIndex& index,
                                              const Mesh& mesh) {
  std::vector<std::array<int, N>> out(cells.node_tags.size() / N);
  for (std::size_t c = 0; c < out.size(); ++c) {
    std::array<int, N> cell;
    for (std::size_t k = 0; k < N; ++k) cell[k] = index.at(cells.node_tags[N * c + k]);
    for (std::size_t k = 0; k < N; ++k)
      if (cell[k] == cell[(k + 1) % N] || (N == 4 && k < 2 && cell[k] == cell[k + 2]))
        throw std::runtime_error("gmsh mesh has a cell whose corners repeat the node at (" +
                                 std::to_string(mesh.nodes(cell[k], 0)) + ", " + std::to_string(mesh.nodes(cell[k], 1)) +
                                 "): a degenerate cell (a crack?)");
    out[c] = counter_clockwise(mesh, cell);
  }
  return out;
}

// A cell side, in the direction it has in its (counter-clockwise) cell, so that cell lies on
// its left; `cells` counts the cells sharing it (1 on the boundary of the extracted mesh).
struct CellSide {
  int from = 0, to = 0;
  int cells = 0;
};
using SideKey = std::pair<int, int>;  // (smaller node, larger node)
using SideMap = std::map<SideKey, CellSide>;

SideKey side_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

template <std::size_t N>
void add_sides(const std::vector<std::array<int, N>>& cells, SideMap& sides) {
  for (const auto& cell : cells) {
    for (std::size_t k = 0; k < N; ++k) {
      const int a = cell[k], b = cell[(k + 1) % N];
      CellSide& side = sides[side_key(a, b)];
      side.from = a;
      side.to = b;
      ++side.cells;
    }
  }
}

SideMap cell_sides(const Mesh& mesh) {
  SideMap sides;
  if (mesh.element == ElementType::Q1)
    add_sides(mesh.quads, sides);
  else
    add_sides(mesh.triangles, sides);
  return sides;
}

std::vector<std::array<std::size_t, 2>> curve_segments(int curve);

// The curve's nodes (its end points included) in the order of its segments: from the end
// where its first segment starts, each next node the other end of the segment not yet
// walked. For a mesh read from a .msh file, which carries no parametric coordinates unless
// written with Mesh.SaveParametric, the segments are all there is to go by.
std::vector<std::size_t> curve_nodes_by_segments(int curve) {
  const auto segments = curve_segments(curve);
  std::map<std::size_t, std::vector<std::size_t>> next;
  for (const auto& [a, b] : segments) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  if (segments.empty()) return {};
  std::size_t start = segments.front()[0];
  for (const auto& [a, b] : segments)  // an open curve starts at the end whose segment leaves it
    if (next[a].size() == 1) {
      start = a;
      break;
    }
  std::vector<std::size_t> order = {start};
  std::set<std::size_t> seen = {start};
  while (true) {
    bool moved = false;
    for (std::size_t n : next[order.back()])
      if (seen.insert(n).second) {
        order.push_back(n);
        moved = true;
        break;
      }
    if (!moved) break;
  }
  if (order.size() != next.size())
    throw std::runtime_error("gmsh curve " + std::to_string(curve) + " has segments that do not form one chain");
  return order;
}

// The curve's nodes (its end points included) by increasing curve parameter, or in the order
// of its segments where the mesh has no parametric coordinates (read from a .msh file).
std::vector<std::size_t> curve_nodes_along(int curve) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, u;
  gmsh::model::mesh::getNodes(tags, xyz, u, 1, curve, /*includeBoundary=*/true,
                              /*returnParametricCoord=*/true);
  if (u.size() != tags.size()) return curve_nodes_by_segments(curve);
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return u[i] < u[j]; });
  std::vector<std::size_t> sorted;
  for (std::size_t i : order) sorted.push_back(tags[i]);
  return sorted;
}

std::vector<std::array<std::size_t, 2>> curve_segments(int curve) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, curve);
  std::vector<std::array<std::size_t, 2>> segments;
  for (std::size_t k = 0; k < types.size(); ++k) {
    if (types[k] != kGmshLine2)
      throw std::runtime_error("gmsh curve " + std::to_string(curve) +
                               " has non-linear elements (gmsh type " + std::to_string(types[k]) +
                               ")");
    for (std::size_t i = 0; i + 1 < node_tags[k].size(); i += 2)
      segments.push_back({node_tags[k][i], node_tags[k][i + 1]});
  }
  return segments;
}

// Appends `node` unless already there: consecutive curves share their junction node.
void append_once(std::vector<int>& nodes, std::set<int>& seen, int node) {
  if (seen.insert(node).second) nodes.push_back(node);
}

void add_point_set(const NamedBoundary& boundary, const NodeIndex& index, Mesh& mesh) {
  std::vector<int> nodes;
  std::set<int> seen;
  for (int point : boundary.tags) {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, parametric;
    gmsh::model::mesh::getNodes(tags, xyz, parametric, 0, point, false, false);
    for (std::size_t tag : tags) {
      auto it = index.find(tag);
      if (it != index.end()) append_once(nodes, seen, it->second);
    }
  }
  if (!nodes.empty()) mesh.node_sets[boundary.name] = std::move(nodes);
}

void add_curve_sets(const NamedBoundary& boundary, const NodeIndex& index, const SideMap& sides,
                    Mesh& mesh) {
  std::vector<int> nodes;
  std::set<int> seen;
  std::vector<std::array<int, 2>> edges;
  for (int curve : boundary.tags) {
    const auto segments = curve_segments(curve);
    std::vector<std::array<int, 2>> curve_edges;
    for (const auto& [a, b] : segments) {
      auto ia = index.find(a), ib = index.find(b);
      if (ia == index.end() || ib == index.end()) continue;
      auto side = sides.find(side_key(ia->second, ib->second));
      if (side == sides.end()) continue;
      if (side->second.cells > 1)
        throw std::runtime_error("boundary '" + boundary.name + "': gmsh curve " +
                                 std::to_string(curve) +
                                 " runs through the interior of the extracted surfaces");
      curve_edges.push_back({side->second.from, side->second.to});
    }
    if (curve_edges.empty()) continue;  // the curve belongs to another body
    if (curve_edges.size() != segments.size())
      throw std::runtime_error("boundary '" + boundary.name + "': gmsh curve " +
                               std::to_string(curve) +
                               " lies only partly on the extracted surfaces");
    for (std::size_t tag : curve_nodes_along(curve)) append_once(nodes, seen, index.at(tag));
    edges.insert(edges.end(), curve_edges.begin(), curve_edges.end());
  }
  if (nodes.empty()) return;
  mesh.node_sets[boundary.name] = std::move(nodes);
  mesh.edge_sets[boundary.name] = std::move(edges);
}

void check_boundary_names(const std::vector<NamedBoundary>& boundaries) {
  std::set<std::string> names;
  for (const auto& boundary : boundaries) {
    if (boundary.name.empty()) throw std::invalid_argument("mesh_from_gmsh: empty boundary name");
    if (boundary.dim != 0 && boundary.dim != 1)
      throw std::invalid_argument("mesh_from_gmsh: boundary '" + boundary.name +
                                  "' has dimension " + std::to_string(boundary.dim) +
                                  "; expected 0 (points) or 1 (curves)");
    if (!names.insert(boundary.name).second)
      throw std::invalid_argument("mesh_from_gmsh: boundary name '" + boundary.name +
                                  "' given twice");
  }
}

}  // namespace

void ensure_gmsh_initialized() { static GmshRuntime runtime; }

void gmsh_new_model(const std::string& name) {
  ensure_gmsh_initialized();
  with_gmsh_errors([&] {
    gmsh::clear();  // drops every model and leaves one empty, unnamed model
    gmsh::model::add(name);
  });
}

int fork_with_gmsh_lock() {
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return ::fork();  // the child's copy of the mutex is unlocked by the guard's copy
}

GmshModelScope::GmshModelScope(const std::string& name) : lock_(gmsh_mutex()) {
  gmsh_new_model(name);
}

GmshModelScope::~GmshModelScope() {
  try {
    gmsh::clear();
  } catch (...) {  // a destructor must not throw; the next scope clears again anyway
  }
}

ScopedGmshOption::ScopedGmshOption(std::string name, double value) : name_(std::move(name)) {
  gmsh::option::getNumber(name_, previous_);
  gmsh::option::setNumber(name_, value);
}

ScopedGmshOption::~ScopedGmshOption() {
  try {
    gmsh::option::setNumber(name_, previous_);
  } catch (...) {  // a destructor must not throw
  }
}

std::vector<int> all_surfaces() {
  gmsh::vectorpair dim_tags;
  gmsh::model::getEntities(dim_tags, 2);
  std::vector<int> tags;
  for (const auto& [dim, tag] : dim_tags) tags.push_back(tag);
  return tags;
}

NamedBoundary physical_group(int dim, int tag, const std::string& name) {
  return with_gmsh_errors([&] {
    NamedBoundary boundary{name, dim, {}};
    if (boundary.name.empty()) gmsh::model::getPhysicalName(dim, tag, boundary.name);
    if (boundary.name.empty())
      throw std::invalid_argument("physical group (" + std::to_string(dim) + ", " +
                                  std::to_string(tag) + ") has no name");
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, boundary.tags);
    return boundary;
  });
}

std::vector<NamedBoundary> named_physical_groups() {
  return with_gmsh_errors([] {
    std::vector<NamedBoundary> boundaries;
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto& [dim, tag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(dim, tag, name);
      if ((dim == 0 || dim == 1) && !name.empty()) boundaries.push_back(physical_group(dim, tag));
    }
    return boundaries;
  });
}

Mesh mesh_from_gmsh(const std::vector<int>& surfaces,
                    const std::vector<NamedBoundary>& boundaries) {
  check_boundary_names(boundaries);
  return with_gmsh_errors([&] {
    const GmshCells cells = collect_cells(surfaces.empty() ? all_surfaces() : surfaces);
    const NodeIndex index = number_used_nodes(cells.node_tags);

    Mesh mesh;
    mesh.element = cells.element;
    fill_coordinates(index, mesh);
    if (mesh.element == ElementType::Q1)
      mesh.quads = convert_cells<4>(cells, index, mesh);
    else
      mesh.triangles = convert_cells<3>(cells, index, mesh);

    const SideMap sides = cell_sides(mesh);
    for (const auto& boundary : boundaries) {
      if (boundary.dim == 0)
        add_point_set(boundary, index, mesh);
      else
        add_curve_sets(boundary, index, sides, mesh);
    }
    return mesh;
  });
}

}  // namespace thinlayer
