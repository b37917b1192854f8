#include "cases/scene/scene_mesh.h"

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <new>
#include <sstream>

#include "cases/scene/mesh_estimate.h"
#include "cases/scene/scene_mesh_child.h"
#include "core/mesh/gmsh_session.h"
#include "core/mesh/meshing_child.h"

namespace thinlayer {

namespace {

// Physical groups by (dimension, name) → model entity tags.
std::map<std::pair<int, std::string>, std::vector<int>> physical_groups() {
  std::map<std::pair<int, std::string>, std::vector<int>> groups;
  gmsh::vectorpair dim_tags;
  gmsh::model::getPhysicalGroups(dim_tags);
  for (const auto& [dim, tag] : dim_tags) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) continue;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    auto& list = groups[{dim, name}];
    list.insert(list.end(), entities.begin(), entities.end());
  }
  return groups;
}

void set_interface_sizes(const SceneSpec& spec, const std::vector<int>& interface_curves) {
  namespace field = gmsh::model::mesh::field;
  const double h_i = *spec.h_interface, h_f = *spec.h_far;
  std::vector<double> curves(interface_curves.begin(), interface_curves.end());
  const int distance = field::add("Distance");
  field::setNumbers(distance, "CurvesList", curves);
  field::setNumber(distance, "NumPointsPerCurve", 200);
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", h_i);
  field::setNumber(threshold, "SizeMax", h_f);
  field::setNumber(threshold, "DistMin", 0);
  field::setNumber(threshold, "DistMax", std::max((h_f - h_i) / kSizeGrowthRate, h_f));
  field::setAsBackgroundMesh(threshold);
  // The field alone decides: no size from the points of the .geo, none from curvature.
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

void generate(const SceneSpec& spec, const std::vector<int>& interface_curves) {
  if (spec.h_interface) set_interface_sizes(spec, interface_curves);
  if (spec.element == ElementType::Q1) {
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 2);  // simple full-quad: no triangle left
    gmsh::option::setNumber("Mesh.Algorithm", 6);               // gmsh's default; 8 crashes (SPEC §7)
  } else {
    gmsh::option::setNumber("Mesh.RecombineAll", 0);
  }
  gmsh::model::mesh::generate(2);
}

double bounding_size(const std::vector<Mesh>& meshes) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  for (const Mesh& m : meshes)
    for (Eigen::Index i = 0; i < m.nodes.rows(); ++i) {
      lo = lo.cwiseMin(m.nodes.row(i).transpose());
      hi = hi.cwiseMax(m.nodes.row(i).transpose());
    }
  return (hi - lo).norm();
}

[[noreturn]] void fail_at(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

// A .geo's points, before meshing: a point off z = 0 makes a surface gmsh cannot mesh flat
// ("Unable to recover the edge") or a mesh out of the plane.
void refuse_off_plane_points(const std::string& file) {
  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  for (const auto& [dim, tag] : points) {
    std::vector<double> xyz;
    gmsh::model::getValue(0, tag, {}, xyz);
    if (xyz.size() == 3 && (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || xyz[2] != 0)) {
      std::ostringstream at;
      at << file << ": point " << tag << " at (" << xyz[0] << ", " << xyz[1] << ", " << xyz[2] << ") ";
      throw InputError(at.str() + (std::isfinite(xyz[2]) && std::isfinite(xyz[0]) && std::isfinite(xyz[1])
                                       ? "is off the plane z = 0: a scene is two-dimensional, its geometry lies in z = 0"
                                       : "has a coordinate that is not a finite number"));
    }
  }
}

// mm: beyond it the areas and the solve's squares of lengths leave the doubles' comfortable range
// (a node at 1e300 was "bodies share the cell"); a joint is far smaller.
constexpr double largest_coordinate = 1e9;

// A scene is two-dimensional: every node of the model lies in z = 0 (a .msh with z != 0 was
// solved as its projection without a word), at finite coordinates (a NaN node was a
// "non-positive area" later). `tolerance`: the z that round-off leaves, mm.
void refuse_off_plane_nodes(const std::string& file, double tolerance) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, /*includeBoundary=*/true, /*returnParametricCoord=*/false);
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const double x = xyz[3 * k], y = xyz[3 * k + 1], z = xyz[3 * k + 2];
    std::ostringstream at;
    at.precision(6);
    at << "node " << tags[k] << " at (" << x << ", " << y << ", " << z << ")";
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw InputError(file + ": " + at.str() + " has a coordinate that is not a finite number");
    if (std::abs(x) > largest_coordinate || std::abs(y) > largest_coordinate)
      throw InputError(file + ": " + at.str() + " lies beyond 1e9 mm of the origin (lengths are in mm)");
    if (std::abs(z) > tolerance)
      throw InputError(file + ": " + at.str() + " is off the plane z = 0: a scene is two-dimensional, its mesh lies in z = 0");
  }
}

}  // namespace

namespace {

// `staged`: the staged copy of the geometry or mesh (scene_mesh_child.h); messages name the user's file.
SceneMeshes mesh_in_this_process(const SceneSpec& spec, const std::string& staged) {
  const auto start = std::chrono::steady_clock::now();
  const std::string file = spec.geometry.empty() ? spec.mesh : spec.geometry;
  meshing_phase(spec.geometry.empty() ? "reading the mesh" : "reading the geometry");
  GmshModelScope scope("scene");
  // gmsh's own options for this model only: the scope clears the model, the options stay
  // process-global, so they are set back when done.
  ScopedGmshOption recombine_all("Mesh.RecombineAll", 0), recombination("Mesh.RecombinationAlgorithm", 1),
      algorithm("Mesh.Algorithm", 6), from_boundary("Mesh.MeshSizeExtendFromBoundary", 1),
      from_points("Mesh.MeshSizeFromPoints", 1), from_curvature("Mesh.MeshSizeFromCurvature", 0);
  SceneMeshes out;
  try {
    with_gmsh_errors([&] { gmsh::open(staged); });
  } catch (const std::bad_alloc&) {
    throw;  // the meshing child says so, with its limit and the phase
  } catch (const std::exception& e) {
    fail_at(spec.geometry_where, "gmsh cannot read " + file + ": " + e.what());
  }
  return with_gmsh_errors([&] {
    const auto groups = physical_groups();
    auto find = [&](int dim, const std::string& name) -> const std::vector<int>* {
      auto it = groups.find({dim, name});
      return it == groups.end() ? nullptr : &it->second;
    };
    for (const auto& [key, tags] : groups) (key.first == 1 ? out.curve_groups : out.point_groups).insert(key.second);
    for (const SceneBodySpec& b : spec.bodies)
      if (!find(2, b.group)) fail_at(b.group_where, "body '" + b.name + "': group '" + b.group + "' is no physical surface of " + file);
    std::vector<int> bondline_curves;  // every bondline's curves: the mesh is finest along them
    for (const SceneInterfaceSpec& i : spec.interfaces) {
      const std::vector<int>* curves = find(1, i.group);
      if (!curves) fail_at(i.group_where, "interface group '" + i.group + "' is no physical curve of " + file);
      bondline_curves.insert(bondline_curves.end(), curves->begin(), curves->end());
    }
    for (const SceneSupportSpec& s : spec.supports)
      if (!find(1, s.group) && !find(0, s.group))
        fail_at(s.where, "support group '" + s.group + "' is no physical curve or point of " + file);
    for (const SceneLoadSpec& l : spec.loads) {
      if (l.kind == LoadKind::Force && !find(1, l.group) && !find(0, l.group))
        fail_at(l.where, "load group '" + l.group + "' is no physical curve or point of " + file);
      if (l.kind != LoadKind::Force && !find(1, l.group))
        fail_at(l.where, "load group '" + l.group + "' is no physical curve of " + file + " (a " + to_string(l.kind) +
                             " acts along a curve; a force may act on a point)");
    }

    if (spec.geometry.empty()) refuse_off_plane_nodes(file, 0.0);  // a .msh: z exactly 0, as gmsh writes a 2D mesh
    else refuse_off_plane_points(file);
    refuse_oversized_mesh(spec);  // bounded before spent (cases/scene/mesh_estimate.h)
    if (!spec.geometry.empty()) {
      meshing_phase("meshing");
      generate(spec, bondline_curves);
      double xmin, ymin, zmin, xmax, ymax, zmax;
      gmsh::model::getBoundingBox(-1, -1, xmin, ymin, zmin, xmax, ymax, zmax);
      // OpenCASCADE's points carry round-off of the order of its tolerance, 1e-7 of the size.
      const double size = std::hypot(xmax - xmin, ymax - ymin);
      refuse_off_plane_nodes(file, std::isfinite(size) ? 1e-6 * std::max(size, 1.0) : 0.0);
    }
    meshing_phase("converting the mesh");
    std::vector<NamedBoundary> boundaries;
    for (const auto& [key, tags] : groups)
      if (key.first <= 1) {
        // A name used for both a curve and a point: the curve wins (a support may be either).
        if (key.first == 0 && groups.count({1, key.second})) continue;
        boundaries.push_back({key.second, key.first, tags});
      }
    for (const SceneBodySpec& b : spec.bodies) {
      Mesh m = mesh_from_gmsh(*find(2, b.group), boundaries);
      if (m.element != spec.element)
        fail_at(b.group_where, "body '" + b.name + "' is meshed with " + to_string(m.element) + " cells, the scene asks for " +
                                   to_string(spec.element));
      out.bodies.push_back(std::move(m));
    }
    out.size = bounding_size(out.bodies);
    out.meshing_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  });
}

}  // namespace

// In the confined meshing child, after the .geo scan (cases/scene/scene_mesh_child.h).
SceneMeshes load_scene_meshes(const SceneSpec& spec) { return mesh_scene_in_child(spec, mesh_in_this_process); }

}  // namespace thinlayer
