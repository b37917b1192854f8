#pragma once
// Access to the gmsh C++ API for building meshes, and conversion of a gmsh 2D mesh into a
// thinlayer::Mesh.
//
// gmsh keeps all of its state (options, models, meshes) in process-wide globals and is not
// thread-safe, so every mesh builder works inside a GmshModelScope:
//
//   GmshModelScope scope("my_geometry");        // exclusive, silent, empty model
//   return with_gmsh_errors([&] {
//     ... gmsh::model::geo::add...; synchronize(); gmsh::model::mesh::generate(2);
//     return mesh_from_gmsh({surface_tag}, {{"bottom", 1, {curve_tag}}, ...});
//   });
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh.h"

namespace thinlayer {

// Initialises gmsh the first time it is called (headless, nothing printed, no user
// configuration files read); gmsh is finalised when the process exits. Idempotent.
void ensure_gmsh_initialized();

// Discards every gmsh model (and its mesh) and makes an empty model named `name` current.
// Initialises gmsh if needed. Prefer GmshModelScope, which also takes the gmsh lock.
void gmsh_new_model(const std::string& name);

// Exclusive use of gmsh for building one model: holds a process-wide lock for its lifetime,
// starts from an empty model named `name`, and discards the model when destroyed so large
// meshes do not linger in gmsh's memory.
class GmshModelScope {
 public:
  explicit GmshModelScope(const std::string& name);
  ~GmshModelScope();
  GmshModelScope(const GmshModelScope&) = delete;
  GmshModelScope& operator=(const GmshModelScope&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
};

// Sets a gmsh number option for the lifetime of the object and restores its value after (gmsh's
// options are process-global).
class ScopedGmshOption {
 public:
  ScopedGmshOption(std::string name, double value);
  ~ScopedGmshOption();
  ScopedGmshOption(const ScopedGmshOption&) = delete;
  ScopedGmshOption& operator=(const ScopedGmshOption&) = delete;

 private:
  std::string name_;
  double previous_ = 0;
};

// The size field of a mesh graded away from its bondlines grows the element size by at most this
// much per unit distance from them: gentle enough for well-shaped quads (the dovetail's and every
// scene file's mesh).
constexpr double kSizeGrowthRate = 0.2;

// The tags of every surface (2D entity) of the current gmsh model.
std::vector<int> all_surfaces();

// fork() while holding the lock of GmshModelScope, so that no other thread of this process is
// inside gmsh at that instant (the child's copy of gmsh is whole); the lock is released in
// both processes. For core/mesh/meshing_child.h.
int fork_with_gmsh_lock();

// gmsh 4.8 reports errors by throwing a bare std::string, which `catch (std::exception&)`
// misses; run `f` and rethrow those as std::runtime_error.
template <class F>
decltype(auto) with_gmsh_errors(F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const std::string& message) {
    throw std::runtime_error("gmsh: " + message);
  }
}

// A named piece of the boundary of the current gmsh model: model entities (not physical
// group tags) of dimension 1 (curves: gives a node set and an edge set) or 0 (points: gives
// a node set only).
struct NamedBoundary {
  std::string name;
  int dim = 1;
  std::vector<int> tags;
};

// The entities of the physical group (dim, tag), named `name` or, if empty, by the group's
// own physical name.
NamedBoundary physical_group(int dim, int tag, const std::string& name = "");

// Every named physical group of dimension 0 or 1 in the current model.
std::vector<NamedBoundary> named_physical_groups();

// Converts the 2D mesh of the current gmsh model into a Mesh.
//
// `surfaces`: tags of the 2D entities to extract (empty: all of them). To get one Mesh per
// body of a multi-body model, call once per body with that body's surfaces.
//
// Cells: all linear quadrangles (-> Q1) or all linear triangles (-> P1); anything else
// (mixed, high order) throws. Cells are reoriented counter-clockwise where needed.
// Nodes: those used by the extracted cells only, numbered 0..N-1 in increasing gmsh tag
// order, z dropped.
//
// Named sets, for each entry of `boundaries`:
//  - points: node set of the points' nodes, in the listed order;
//  - curves: node set of the curves' nodes, each curve's nodes sorted by increasing curve
//    parameter (i.e. following the curve's orientation in gmsh; for a mesh read from a .msh
//    without parametric coordinates, following its segments), curves taken in the listed
//    order, nodes shared by consecutive curves kept once; so list the curves head to tail to
//    get a node set sorted along the boundary. Edge set: the curves' mesh segments in gmsh's
//    order along each curve, each as (a, b) with the body on the left, which is the
//    counter-clockwise direction around the body whatever the curve's own orientation.
// Entities that do not lie on the extracted surfaces are ignored, and a name with none left
// gets no set: the same list of names can serve every body. A named curve running through
// the interior of the extracted surfaces throws (its segments have no single "left").
Mesh mesh_from_gmsh(const std::vector<int>& surfaces, const std::vector<NamedBoundary>& boundaries);

}  // namespace thinlayer
