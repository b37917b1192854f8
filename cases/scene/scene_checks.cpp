#include "cases/scene/scene_checks.h"

#include "core/io/shown_text.h"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace thinlayer {

namespace {

[[noreturn]] void fail_at(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// `dataset`: the results file's group the name becomes a member of ("reactions/"), or "".
void check_name(const std::string& where, const std::string& what, const std::string& name, const std::string& dataset) {
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f)
      fail_at(where, what + " '" + shown(name) + "' holds a control character (the results file's names are text)");
  if (!dataset.empty() && (name.find('/') != std::string::npos || name == "." || name == ".."))
    fail_at(where, what + " '" + name + "' names a dataset of the results file (" + dataset + name +
                       "): it may hold no '/' and be no '.' or '..'");
}

void check_names(const SceneSpec& spec, const PositionedJson& doc) {
  {
    const TextPosition p = doc.at("/name");
    const std::string where = doc.source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
    check_name(where, "'name'", spec.name, "");  // printed in tables and the report's title
    if (spec.name.find_first_not_of('.') == std::string::npos)
      fail_at(where, "'name' '" + spec.name + "' names no group of the results file (/studies/scene/<name>): give it a letter or digit");
  }
  for (const SceneBodySpec& b : spec.bodies) {
    check_name(b.where, "body name", b.name, "");
    check_name(b.group_where, "body '" + shown(b.name) + "': group", b.group, "");
  }
  for (const SceneInterfaceSpec& i : spec.interfaces)  // in the list form, interface/<group>/S
    check_name(i.group_where, "bondline group", i.group, spec.interface_list ? "interface/" : "");
  for (const SceneSupportSpec& s : spec.supports) check_name(s.where, "support group", s.group, "reactions/");
  for (const SceneLoadSpec& l : spec.loads) check_name(l.where, "load group", l.group, "loads/");
}

bool is_bondline(const SceneSpec& spec, const std::string& group) {
  for (const SceneInterfaceSpec& i : spec.interfaces)
    if (i.group == group) return true;
  return false;
}

void check_materials(const SceneSpec& spec) {
  for (const SceneBodySpec& b : spec.bodies)
    if (const std::string why = material_fault(b.lambda, b.mu); !why.empty()) fail_at(b.where, "body '" + b.name + "' " + why);
}

void check_groups(const SceneSpec& spec) {
  std::map<std::string, std::string> body_of;
  for (const SceneBodySpec& b : spec.bodies)
    if (auto [it, fresh] = body_of.emplace(b.group, b.name); !fresh)
      fail_at(b.group_where, "bodies '" + it->second + "' and '" + b.name + "' are the same physical surface '" + b.group +
                                 "': each body is a surface of its own");
  std::map<std::string, std::size_t> support_of, load_of;
  for (std::size_t k = 0; k < spec.supports.size(); ++k) {
    const SceneSupportSpec& s = spec.supports[k];
    if (is_bondline(spec, s.group))
      fail_at(s.where, "support on the bondline '" + s.group + "': its nodes are in contact, not held (support a "
                       "curve of a body's boundary away from it)");
    if (auto [it, fresh] = support_of.emplace(s.group, k); !fresh)
      fail_at(s.where, "support group '" + s.group + "' is given twice (supports " + std::to_string(it->second) + " and " +
                           std::to_string(k) + "): give each group one support");
  }
  for (std::size_t k = 0; k < spec.loads.size(); ++k) {
    const SceneLoadSpec& l = spec.loads[k];
    if (is_bondline(spec, l.group))
      fail_at(l.where, "load on the bondline '" + l.group + "': it carries the contact between the bodies, not a load");
    // Each load is written as loads/<group> too: one load per group.
    if (auto [it, fresh] = load_of.emplace(l.group, k); !fresh)
      fail_at(l.where, "load group '" + l.group + "' is given twice (loads " + std::to_string(it->second) + " and " +
                           std::to_string(k) + "): they would add up; give their sum once");
  }
}

std::string point_of(const Mesh& m, int node) {
  std::ostringstream s;
  s << "(" << m.nodes(node, 0) << ", " << m.nodes(node, 1) << ")";
  return s.str();
}

// The centre of every cell, rounded to 1e-9 of the model's size: a cell of two bodies shows up twice.
void check_shared_cells(const SceneSpec& spec, const SceneMeshes& meshes) {
  const double grain = 1e-9 * std::max(meshes.size, 1e-300);
  std::map<std::pair<long long, long long>, std::size_t> owner;
  for (std::size_t b = 0; b < meshes.bodies.size(); ++b) {
    const Mesh& m = meshes.bodies[b];
    auto visit = [&](const auto& cell) {
      Eigen::Vector2d centre = Eigen::Vector2d::Zero();
      for (int n : cell) centre += m.nodes.row(n).transpose() / static_cast<double>(cell.size());
      const std::pair<long long, long long> key{std::llround(centre.x() / grain), std::llround(centre.y() / grain)};
      if (auto [it, fresh] = owner.emplace(key, b); !fresh && it->second != b)
        fail_at(spec.bodies[b].group_where, "bodies '" + spec.bodies[it->second].name + "' and '" + spec.bodies[b].name +
                                                "' share the cell at (" + number(centre.x()) + ", " + number(centre.y()) +
                                                "): their groups hold the same surface");
    };
    for (const auto& q : m.quads) visit(q);
    for (const auto& t : m.triangles) visit(t);
  }
}

// Per body and node, the value each support prescribes to each component; the bondline's nodes.
void check_supports_on_nodes(const SceneSpec& spec, const SceneMeshes& meshes) {
  for (std::size_t b = 0; b < meshes.bodies.size(); ++b) {
    const Mesh& m = meshes.bodies[b];
    std::map<int, std::string> bondline;  // node -> its bondline's group
    for (const SceneInterfaceSpec& i : spec.interfaces)
      if (auto it = m.node_sets.find(i.group); it != m.node_sets.end())
        for (int n : it->second) bondline.emplace(n, i.group);
    std::map<std::pair<int, int>, std::pair<double, const SceneSupportSpec*>> prescribed;  // (node, component) -> value, by
    for (const SceneSupportSpec& s : spec.supports) {
      auto nodes = m.node_sets.find(s.group);
      if (nodes == m.node_sets.end()) continue;
      for (int n : nodes->second) {
        if (auto on = bondline.find(n); on != bondline.end())
          fail_at(s.where, "support group '" + s.group + "' holds the node " + point_of(m, n) + " of the bondline '" +
                               on->second + "' (body '" + spec.bodies[b].name +
                               "'): a node in contact cannot also be prescribed");
        for (int c = 0; c < 2; ++c) {
          if (!s.u[c]) continue;
          auto [it, fresh] = prescribed.emplace(std::pair{n, c}, std::pair{*s.u[c], &s});
          if (!fresh && it->second.first != *s.u[c])
            fail_at(s.where, "supports '" + it->second.second->group + "' and '" + s.group + "' prescribe u_" +
                                 (c == 0 ? "x" : "y") + " = " + number(it->second.first) + " and " + number(*s.u[c]) +
                                 " mm to the node " + point_of(m, n) + " of body '" + spec.bodies[b].name + "'");
        }
      }
    }
  }
}

// A Q1 cell's Jacobian at each corner: the cross product of its two sides there.
void check_cells(const SceneSpec& spec, const SceneMeshes& meshes) {
  const std::string file = spec.geometry.empty() ? spec.mesh : spec.geometry;
  for (std::size_t b = 0; b < meshes.bodies.size(); ++b) {
    const Mesh& m = meshes.bodies[b];
    for (const auto& q : m.quads)
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector2d p = m.nodes.row(q[k]), next = m.nodes.row(q[(k + 1) % 4]), previous = m.nodes.row(q[(k + 3) % 4]);
        const Eigen::Vector2d a = next - p, c = previous - p;
        if (!(a.x() * c.y() - a.y() * c.x() > 0))
          fail_at(file, "body '" + spec.bodies[b].name + "': the cell with a corner at " + point_of(m, q[k]) +
                            " is inverted or not convex (non-positive Jacobian there)");
      }
  }
}

}  // namespace

std::string material_fault(double lambda, double mu) {
  if (!(mu > 0)) return "is no material: mu = " + number(mu) + " daN/mm^2 must be > 0 (its shear modulus)";
  if (!(3 * lambda + 2 * mu > 0)) {
    const double nu = lambda / (2 * (lambda + mu));
    return "is no material: 3 lambda + 2 mu = " + number(3 * lambda + 2 * mu) +
           " daN/mm^2 must be > 0 (its bulk modulus; Poisson's ratio nu = " + number(nu) + " is outside (-1, 0.5))";
  }
  return "";
}

void check_scene_spec(const SceneSpec& spec, const PositionedJson& doc) {
  check_names(spec, doc);
  check_materials(spec);
  check_groups(spec);
}

void check_scene_mesh_data(const SceneSpec& spec, const SceneMeshes& meshes) {
  check_shared_cells(spec, meshes);
  check_supports_on_nodes(spec, meshes);
  check_cells(spec, meshes);
}

}  // namespace thinlayer
