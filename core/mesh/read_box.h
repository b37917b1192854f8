#pragma once
// The meshing child's file-system box (SPEC §4: gmsh reads only the bytes thinlayer read and
// checked): with Landlock (Linux >= 5.13, when the kernel has it enabled), the calling process
// and its future threads may read files and list folders beneath one folder — the private
// staging folder of cases/scene/scene_sources.h — and nothing else anywhere: no other read, no
// write, no exec, no new file, folder, link, device or FIFO, whatever the path. Files already
// open (the pipe to the parent, /dev/null) stay usable.
//
// Where the kernel has no Landlock (older, or built without it), nothing is restricted here:
// gmsh is then handed only paths inside the staging folder and its working directory is that
// folder, and the seccomp filter of core/mesh/meshing_child.h still denies writes and exec;
// a read of another path that the .geo scan missed would succeed (docs/security.md, "The box").
#include <string>

namespace thinlayer {

enum class ReadBox {
  Landlock,     // every read outside the folder is denied by the kernel
  StagingOnly,  // no Landlock here: gmsh is only given the staged paths
};

// The Landlock ABI version this kernel offers (0: none). Cheap; callable from any process.
int landlock_abi();

// Confines the calling process to reading beneath `folder` (see above). Returns
// ReadBox::StagingOnly when the kernel has no Landlock; throws std::runtime_error when Landlock
// is there but the confinement fails (the caller must then not run gmsh).
ReadBox confine_reads_to(const std::string& folder);

// The whole box, for the results' /environment: "Landlock ABI 7; user, mount and network namespaces
// (...); seccomp allow-list" on this machine; "no Landlock", "no namespaces" where there are none.
std::string read_box_description();

}  // namespace thinlayer
