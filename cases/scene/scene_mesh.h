#pragma once
// The meshes of a scene file's bodies (SPEC §5): a gmsh .geo meshed here, headless and quiet,
// or a .msh 4.1 used as is. One Mesh per body (its physical surface), each carrying a node set
// (and, for curves, an edge set) for every named physical curve or point that touches it.
#include <set>
#include <string>
#include <vector>

#include "cases/scene/scene_spec.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

struct SceneMeshes {
  std::vector<Mesh> bodies;            // in the order of SceneSpec::bodies
  std::set<std::string> curve_groups;  // named physical curves of the model
  std::set<std::string> point_groups;  // named physical points
  double size = 0;                     // the diagonal of the bounding box of all nodes, mm
  double meshing_time_s = 0;
};

// Meshes (or reads) the scene's geometry. Q1: quads by recombination with gmsh's default 2D
// algorithm (its algorithm 8 crashes in Debian's gmsh 4.8, SPEC §7) and the "simple full-quad"
// recombination, which leaves no triangle; P1: triangles. `mesh_size` (if given): the element
// size h_interface on the interface curves growing linearly to h_far away from them.
// A group missing from the mesh, or of the wrong dimension, is an InputError at its line and
// column in the scene file; so is a gmsh error reading the geometry.
SceneMeshes load_scene_meshes(const SceneSpec& spec);

}  // namespace thinlayer
