#pragma once
// A scene's meshes made the safe way (SPEC §4, "Nothing runs that the user did not ask for"):
// its .geo scanned first (cases/scene/geo_scan.h), then gmsh run in the confined meshing child
// (core/mesh/meshing_child.h), which hands the meshes back. Every failure, a crash of gmsh
// included, is one InputError naming the geometry (or mesh) file; a mesh above
// SceneSpec::max_nodes is refused (estimated before meshing: cases/scene/mesh_estimate.h;
// counted after).
#include <functional>

#include "cases/scene/scene_mesh.h"
#include "core/io/output_ownership.h"

namespace thinlayer {

// The files a scene run reads: the scene file, its geometry or mesh, and what the geometry
// includes or merges (geo_scan.h). No output may replace them.
std::vector<InputFile> scene_inputs(const SceneSpec& spec);

// `mesh` runs in the child; it meshes `spec` with gmsh in-process (scene_mesh.cpp).
SceneMeshes mesh_scene_in_child(const SceneSpec& spec, const std::function<SceneMeshes(const SceneSpec&)>& mesh);

}  // namespace thinlayer
