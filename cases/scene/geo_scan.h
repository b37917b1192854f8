#pragma once
// What a scene's gmsh .geo may do (SPEC §4, "Nothing runs that the user did not ask for").
//
// A .geo is a program: gmsh's script language can run a shell command, write files, stop the
// process, mesh on its own and change gmsh's global options. Loading a scene must do none of
// that, so the .geo (and every file it includes or merges) is read here, token by token, with
// gmsh's lexical rules (Parser/Gmsh.l of gmsh 4.8: strings in "..." or '...' without escapes,
// // and /* */ comments, identifiers [A-Za-z_][A-Za-z_0-9]*), before gmsh sees it. Refused,
// wherever they appear (in a loop, a macro, a branch never taken: the scan does not run the
// script, so it refuses what the script could reach):
//   - running something: System, SystemCall, NonBlockingSystemCall, OnelabRun (a command),
//     Plugin (gmsh's plugins, some of which write files), Sleep (stalls the run);
//   - writing: Save, Print, CreateDir, SendToServer, Printf(...) > or >> a file;
//   - stopping: Exit (ends the process with status 0 and no word), Abort;
//   - meshing inside the script (thinlayer meshes it, with the scene's mesh_size): Mesh N,
//     RefineMesh, RecombineMesh, OptimizeMesh, AdaptMesh, SetOrder, PartitionMesh,
//     RelocateMesh, RenumberMeshNodes, RenumberMeshElements, ClassifySurfaces, CreateTopology,
//     CreateGeometry, Homology, Cohomology, Betti, Remesh;
//   - gmsh's process-wide options other than Geometry.* and Mesh.* (General.*, Solver.*,
//     PostProcessing.*, Print.*, View.*: terminal output, solver executables, ...), and
//     SetNumber/SetString (ONELAB parameters, which name solvers too);
//   - a name built at run time (S2N, StringToName), which could spell any command above;
//   - Include, Merge, MergeWithBoundingBox, ShapeFromFile, ListFromFile of anything but a
//     file name in quotes inside the scene's folder (symbolic links followed); an included or
//     merged script (any file but a mesh or CAD file) is scanned in turn.
// What stays allowed is geometry (points, curves, surfaces, physical groups, OpenCASCADE),
// variables, loops, macros, Geometry.* and Mesh.* options and mesh constraints (Transfinite,
// Recombine, Field). A loop can still run long: the meshing child's limits bound it
// (core/mesh/meshing_child.h).
#include <string>
#include <vector>

namespace thinlayer {

// Throws InputError "<file>:<line>: '<word>' <what it does>: refused in a scene's geometry" for
// the first refused statement of `geo` or of a file it includes; `scene_folder` is the folder
// every included or merged file must lie in. Returns every file the geometry reads (`geo`, the
// files it includes or merges, the shapes and lists it reads): the run's inputs, which no
// output may replace (core/io/output_ownership.h).
std::vector<std::string> scan_geo(const std::string& geo, const std::string& scene_folder);

}  // namespace thinlayer
