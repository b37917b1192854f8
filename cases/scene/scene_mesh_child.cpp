#include "cases/scene/scene_mesh_child.h"

#include <sstream>

#include "cases/scene/geo_scan.h"
#include "core/mesh/mesh_bytes.h"
#include "core/mesh/meshing_child.h"

namespace thinlayer {

namespace {

// Every field of SceneMeshes travels from the child: a field added to it must be added here.
static_assert(sizeof(SceneMeshes) == sizeof(std::vector<Mesh>) + 2 * sizeof(std::set<std::string>) + 2 * sizeof(double),
              "SceneMeshes changed: make the new field travel from the meshing child (put/get below)");

void put(ByteWriter& w, const SceneMeshes& m) {
  put(w, m.bodies), put(w, std::vector<std::string>(m.curve_groups.begin(), m.curve_groups.end()));
  put(w, std::vector<std::string>(m.point_groups.begin(), m.point_groups.end())), put(w, m.size), put(w, m.meshing_time_s);
}

void get(ByteReader& r, SceneMeshes& m) {
  std::vector<std::string> curves, points;
  get(r, m.bodies), get(r, curves), get(r, points), get(r, m.size), get(r, m.meshing_time_s);
  m.curve_groups = {curves.begin(), curves.end()};
  m.point_groups = {points.begin(), points.end()};
}

// The mesh gmsh made, counted (the estimate before meshing is an estimate).
void refuse_overgrown(const SceneSpec& spec, const SceneMeshes& meshes) {
  std::size_t nodes = 0;
  for (const Mesh& m : meshes.bodies) nodes += static_cast<std::size_t>(m.num_nodes());
  if (nodes > spec.max_nodes) {
    std::ostringstream s;
    s << spec.geometry_where << ": the mesh has " << nodes << " nodes, above the limit of " << spec.max_nodes
      << " (--max-nodes): coarsen it or raise the limit";
    throw InputError(s.str());
  }
}

}  // namespace

std::vector<InputFile> scene_inputs(const SceneSpec& spec) {
  std::vector<InputFile> inputs = {{spec.file, "the scene file"}};
  if (!spec.mesh.empty()) inputs.push_back({spec.mesh, "its mesh"});
  if (!spec.geometry.empty()) {
    inputs.push_back({spec.geometry, "its geometry"});
    for (const std::string& file : scan_geo(spec.geometry, spec.folder)) inputs.push_back({file, "a file its geometry reads"});
  }
  return inputs;
}

SceneMeshes mesh_scene_in_child(const SceneSpec& spec, const std::function<SceneMeshes(const SceneSpec&)>& mesh) {
  if (!spec.geometry.empty()) scan_geo(spec.geometry, spec.folder);
  const std::string file = spec.geometry.empty() ? spec.mesh : spec.geometry;
  std::string bytes;
  try {
    bytes = run_in_meshing_child([&] {
      const SceneMeshes meshes = mesh(spec);
      refuse_overgrown(spec, meshes);
      ByteWriter w;
      put(w, meshes);
      return w.take();
    });
  } catch (const MeshingChildError& e) {
    if (e.input) throw InputError(e.what());  // it names the scene file's line, or the .geo's
    throw InputError(file + ": " + e.what());
  }
  ByteReader r(bytes);
  SceneMeshes meshes;
  get(r, meshes);
  return meshes;
}

}  // namespace thinlayer
