#pragma once
// What a scene's gmsh script may say (SPEC §4, "Nothing runs that the user did not ask for"):
// the message, not the guarantee. The guarantee is by construction (cases/scene/scene_sources.h):
// gmsh reads only the bytes thinlayer read and scanned, staged in a private folder, in a box that
// denies exec, writes and every other read, under a clock (core/mesh/meshing_child.h). The scan
// says, with the file and line, what a script would try; whatever it missed is then harmless.
//
// A .geo is a program: gmsh's script language can run a shell command, write files, stop the
// process, mesh on its own and change gmsh's global options. The scan reads the text with gmsh's
// lexical rules (Parser/Gmsh.l of gmsh 4.8): strings in "..." or '...' without escapes and at
// most 1023 bytes (gmsh reads the rest of a longer one as statements), // and /* */ comments,
// identifiers [A-Za-z_][A-Za-z_0-9]*, numbers as gmsh reads them (so "1e5System" is a number
// and a keyword, as for gmsh). A NUL byte is refused: gmsh ends a comment or a string there, a
// text editor does not. Refused, wherever they appear (in a loop, a macro, a branch never taken:
// the scan does not run the script, so it refuses what the script could reach):
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
//   - reading the machine rather than the scene's files: GetEnv (the user's environment),
//     FileExists (a probe of the file system), AbsolutePath, CurrentDir(ectory), CurrentFileName,
//     DirName, FixRelativePath, GmshExecutableName (paths of this machine), GetValue and
//     GetStringValue (the terminal), GetNumber, GetString, OnelabAction (ONELAB's parameters),
//     Today, Cpu, Memory, TotalMemory (the machine's clock and memory): a result depends on the
//     scene's files alone, and carries nothing of the machine's;
//   - Include, Merge, MergeWithBoundingBox, ShapeFromFile, ListFromFile of anything but one file
//     name in quotes (a computed name cannot be checked); which names and files are accepted is
//     scene_sources.h's to say.
// What stays allowed is geometry (points, curves, surfaces, physical groups, OpenCASCADE),
// variables, loops, macros, Geometry.* and Mesh.* options and mesh constraints (Transfinite,
// Recombine, Field). A loop can still run long: the meshing child's clock bounds it.
#include <string>
#include <vector>

namespace thinlayer {

// A file a script names: `Include "part.geo";` reads part.geo as a script, `Merge "m.msh";` by
// its extension, ShapeFromFile a CAD shape, ListFromFile numbers.
struct GeoReference {
  enum Kind { Include, Merge, Shape, List } kind = Include;
  std::string word;  // the statement as written ("Include", "MergeWithBoundingBox", ...)
  std::string name;  // the file name, as written between the quotes
  int line = 1;
};

// Gmsh's limit on a string (Parser/Gmsh.l: a 1024-byte buffer with its NUL).
constexpr std::size_t geo_string_max = 1023;

// Scans the script `text` (the bytes of the file `source`, named in messages). Throws InputError
// "<source>:<line>: '<word>' <what it does>: refused in a scene's geometry" for the first refused
// statement; returns the files the script names, in order.
std::vector<GeoReference> scan_geo_text(const std::string& text, const std::string& source);

}  // namespace thinlayer
