#pragma once
// Bounded before spent (SPEC §4): a scene's mesh is refused above SceneSpec::max_nodes
// (`--max-nodes`, default 2·10⁶) from an estimate of its size, before gmsh meshes a surface.
//
// The estimate counts nodes as c ∫ dA / h(x)², h the element size, c the nodes per h² of
// area (measured on gmsh's meshes: c_P1 ≈ 1.2, a Delaunay triangle mesh; c_Q1 ≈ 2.5, the
// full-quad recombination splitting every cell), over every surface gmsh will mesh (a surface
// in no body too: gmsh meshes it all the same). The areas come from the boundary curves,
// sampled 64 times each (no meshing); the sizes:
//   - with the scene's mesh_size: h = h_interface on the bondline growing linearly (0.2 per
//     mm, scene_mesh.cpp) to h_far, clipped by the .geo's Mesh.MeshSizeMin/Max and scaled by
//     Mesh.MeshSizeFactor, as gmsh does, integrated over a band along the bondline; h_far on a
//     surface in no body;
//   - with the .geo's own sizes (points, fields, Transfinite): gmsh meshes the curves only,
//     with a floor on the element size (the surfaces' total boundary length / max_nodes, so that
//     this pass itself stays bounded; MeshSizeFactor cannot take a size under it), and h is the
//     mean segment length of each surface's boundary. The curve mesh is then cleared.
// A mesh read from a .msh is counted as it is.
//
// The estimate is bounded itself (a Transfinite count of 1e8 ignores every size): in the meshing
// child it may take estimate_memory_bytes more memory and estimate_seconds of wall clock; beyond
// either it is refused, naming the geometry (the command's --mesh-timeout may end it first).
#include "cases/scene/scene_spec.h"

namespace thinlayer {

// 512 MiB: the lap joint's pass takes a few MB; the curve pass at its floor (max_nodes segments) about 300 MB.
constexpr long long estimate_memory_bytes = 512LL << 20;
constexpr double estimate_seconds = 60;

// With the scene's geometry open in gmsh (the current model): throws InputError at the scene's
// "geometry" key when the estimate exceeds spec.max_nodes, saying the estimate and what to do.
void refuse_oversized_mesh(const SceneSpec& spec);

// The estimate itself (nodes), for the tests.
double estimated_mesh_nodes(const SceneSpec& spec);

}  // namespace thinlayer
