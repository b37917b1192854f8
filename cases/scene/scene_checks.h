#pragma once
// Everything about a scene that can be checked before solving is checked before solving (SPEC
// §4): a run never spends its time and then fails at the write. Each failure is one
// InputError naming the scene file, line and column (or the mesh's body and point), and why.
//
// On the scene's data (SceneSpec), whatever keys gave them:
//   - names: the scene's name is no HDF5 path ('.', '..'); a name (body, group) holds no
//     control character (a NUL cut the results file's strings short) and a group that names a
//     results dataset (reactions/<group>, loads/<group>, interface/<group> of the list form) no
//     '/' and is no '.' or '..';
//   - materials: a valid 3D isotropic one, μ > 0 and 3λ + 2μ > 0 (bulk modulus > 0, Poisson's
//     ratio in (−1, 1/2)), in plane strain and plane stress alike;
//   - supports and loads: each group once (a second support of the same group was silently
//     ignored, a second load added up; both are written as supports/<group>, loads/<group>),
//     none on a bondline;
//   - two bodies on the same physical surface.
// On its meshes (after gmsh, before any assembly):
//   - two bodies sharing cells (the same surface under two group names);
//   - a node of a bondline that a support also holds (the solvers treat an interface node as
//     free: the solve failed with "interface node with a prescribed displacement component");
//   - two supports prescribing different displacements to one node;
//   - a Q1 cell inverted or not convex (a non-positive Jacobian at a corner).
#include <string>

#include "cases/scene/json_positions.h"
#include "cases/scene/scene_mesh.h"
#include "cases/scene/scene_spec.h"

namespace thinlayer {

// "" for a valid 3D isotropic material with Lamé coefficients λ, μ (daN/mm²), else why not
// ("is no material: ..."), to follow the body's name.
std::string material_fault(double lambda, double mu);

// The checks on the data; `doc` gives the positions of the scene file's keys.
void check_scene_spec(const SceneSpec& spec, const PositionedJson& doc);

// The checks on the meshes.
void check_scene_mesh_data(const SceneSpec& spec, const SceneMeshes& meshes);

}  // namespace thinlayer
