#pragma once
// The files gmsh reads for a scene, resolved, read and checked by thinlayer itself (SPEC §4,
// "Nothing runs that the user did not ask for": gmsh reads only the bytes thinlayer read and
// checked).
//
// thinlayer follows the scene's geometry (its .geo, what it includes and merges, the shapes and
// lists it reads) or mesh the way gmsh 4.8 would (a name is relative to the folder of the file
// that names it, Common/OS.cpp's FixRelativePath), reads each file once, checks it, and keeps its
// bytes. The meshing child is then given a private staging folder holding exactly those bytes
// under the same relative names (core/mesh/staging_folder.h) and nothing else — no `.geo.opt`
// beside the .geo, which gmsh would merge unasked — and may read nothing else
// (core/mesh/read_box.h). What thinlayer cannot check is refused, with the file and line:
//   - a name that is empty, absolute (or "C:/..."-like, which gmsh takes as absolute), holds a
//     backslash (gmsh splits names at '\' as at '/'), or leaves the scene's folder (by "..", or a
//     symbolic link to elsewhere: the file itself must lie in the folder);
//   - a file that is not a regular file (a FIFO would block the reader, a device is no file);
//   - a script (the .geo, an Include, a .geo merged) or a list (ListFromFile: numbers, scanned
//     all the same, so that every file staged for gmsh has passed the scan) holding a NUL byte or
//     refused by the scan (cases/scene/geo_scan.h), or a script beginning with '$' (gmsh would
//     read it as a mesh or a view); an include loop (a file that includes itself, directly or not);
//   - a file whose name ends in ".opt", whatever statement names it: after merging a file F gmsh
//     merges F.opt unasked, as a script (gmsh's only merge-time side file: Common/OpenFile.cpp,
//     MergeFile). None is ever staged; and the box denies gmsh the stat() by which it looks for one
//     (core/mesh/meshing_child.h), so a side file would be inert even if it were there;
//   - a mesh (the scene's "mesh", a Merge of a .msh) that does not begin with `$MeshFormat`:
//     gmsh picks its reader from that first line and reads anything else as a script;
//   - a Merge of any other extension (gmsh picks the reader by the extension, exactly as
//     written: ".Msh", ".xao", ".inp", ".gz" ... are read as scripts, by other readers, or
//     uncompressed by running gunzip), or a shape that is not a STEP (.step, .stp: it begins
//     with ISO-10303-21) or an OpenCASCADE .brep (it says "CASCADE Topology" in its first line);
//   - more than the bounds below.
#include <memory>
#include <string>
#include <vector>

namespace thinlayer {

// Bounds (SPEC §4: bounded before spent). The lap joint's .geo is 2 KB.
constexpr std::size_t max_script_bytes = 4u << 20;   // every script and list of a scene together
constexpr std::size_t max_mesh_bytes = 1u << 30;     // each mesh (a 2·10⁶-node .msh is about 150 MB)
constexpr std::size_t max_shape_bytes = 256u << 20;  // each CAD shape
constexpr std::size_t max_source_files = 256;
constexpr int max_include_depth = 16;

struct SceneSource {
  enum Kind { Script, Mesh, Shape, List } kind = Script;
  std::string path;    // the user's file: the scene's folder joined with `staged`, for messages and as a run's input
  std::string staged;  // its name in the staging folder: relative, lexically normal
  std::string bytes;   // exactly what was read and checked: what gmsh will read
};

struct SceneSources {
  std::string entry;                 // the staged name of the geometry or mesh gmsh opens
  std::vector<std::string> folders;  // the folders to make in the staging folder, parents first
  std::vector<SceneSource> files;    // the entry first
};

// Reads the scene's geometry (`mesh` false) or mesh named `name` in its JSON (relative to the
// scene's `folder`, or absolute inside it), and everything it reads, as above. `where` is
// "<scene file>:<line>:<column>" of that name. Throws InputError naming the file and line.
SceneSources read_scene_sources(const std::string& folder, const std::string& name, bool mesh, const std::string& where);

}  // namespace thinlayer
