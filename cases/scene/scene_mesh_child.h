#pragma once
// A scene's meshes made the safe way (SPEC §4, "Nothing runs that the user did not ask for"):
// the bytes thinlayer read and checked of its geometry or mesh and every file that reads
// (cases/scene/scene_sources.h) staged in a private folder (core/mesh/staging_folder.h), and
// gmsh run on them in the confined meshing child (core/mesh/meshing_child.h): no exec, no
// write, no read outside that folder, a wall clock (--mesh-timeout). The child hands the
// meshes back. Every failure, a crash of gmsh included, is one InputError naming the geometry
// (or mesh) file and the phase; a mesh above SceneSpec::max_nodes is refused (estimated before
// meshing: cases/scene/mesh_estimate.h; counted after).
#include <functional>

#include "cases/scene/scene_mesh.h"
#include "core/io/output_ownership.h"

namespace thinlayer {

// The files a scene run reads: the scene file, its geometry or mesh, and what the geometry
// includes or merges (scene_sources.h). No output may replace them.
std::vector<InputFile> scene_inputs(const SceneSpec& spec);

// `mesh(spec, file)` runs in the child, in the staging folder; it meshes `spec` with gmsh
// in-process from the staged `file` (scene_mesh.cpp).
SceneMeshes mesh_scene_in_child(const SceneSpec& spec,
                                const std::function<SceneMeshes(const SceneSpec&, const std::string&)>& mesh);

}  // namespace thinlayer
