#include "cases/scene/scene_mesh_child.h"

#include <memory>
#include <sstream>

#include "core/mesh/mesh_bytes.h"
#include "core/mesh/meshing_child.h"
#include "core/mesh/staging_folder.h"

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

// gmsh's messages name the staged copy; the user knows the file by its own name.
std::string in_user_terms(std::string message, const std::string& staging_root, const std::string& folder) {
  const std::string staged = staging_root + "/", user = folder.empty() || folder == "." ? "" : folder + "/";
  for (std::size_t at = message.find(staged); at != std::string::npos; at = message.find(staged, at + user.size()))
    message.replace(at, staged.size(), user);
  return message;
}

}  // namespace

std::vector<InputFile> scene_inputs(const SceneSpec& spec) {
  std::vector<InputFile> inputs = {{spec.file, "the scene file"}};
  if (!spec.sources) return inputs;
  for (const SceneSource& f : spec.sources->files)
    inputs.push_back({f.path, &f == &spec.sources->files.front() ? (spec.mesh.empty() ? "its geometry" : "its mesh")
                                                                  : "a file its geometry reads"});
  return inputs;
}

SceneMeshes mesh_scene_in_child(const SceneSpec& spec,
                                const std::function<SceneMeshes(const SceneSpec&, const std::string&)>& mesh) {
  if (!spec.sources) throw std::logic_error("mesh_scene_in_child: the scene's sources were not read");
  const std::string file = spec.geometry.empty() ? spec.mesh : spec.geometry;
  std::vector<StagedFile> files;
  for (const SceneSource& f : spec.sources->files) files.push_back({f.staged, &f.bytes});
  std::unique_ptr<StagingFolder> staging;
  try {
    staging = std::make_unique<StagingFolder>(spec.sources->folders, files);
  } catch (const std::runtime_error& e) {
    throw InputError(file + ": " + e.what());
  }
  MeshingChildLimits limits;  // the wall clock: the command's (set_meshing_wall_clock)
  limits.read_folder = staging->root();
  const std::string entry = staging->root() + "/" + spec.sources->entry;
  std::string bytes;
  try {
    bytes = run_in_meshing_child(
        [&] {
          const SceneMeshes meshes = mesh(spec, entry);
          refuse_overgrown(spec, meshes);
          ByteWriter w;
          put(w, meshes);
          return w.take();
        },
        limits);
  } catch (const MeshingChildError& e) {
    const std::string what = in_user_terms(e.what(), staging->root(), spec.folder);
    if (e.input) throw InputError(what);  // it names the scene file's line, or the .geo's
    throw InputError(file + ": " + what);
  }
  ByteReader r(bytes);
  SceneMeshes meshes;
  get(r, meshes);
  if (!r.done()) throw InputError(file + ": the meshing process answered more than the meshes");
  return meshes;
}

}  // namespace thinlayer
