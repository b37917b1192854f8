#pragma once
// The meshing child's file system cut down to one folder (SPEC §4: gmsh learns nothing of the
// machine's files, not even by stat). Landlock, however recent, decides opens, not lookups: a
// stat(), a readlink() or an access() of any path still answers under it. So the child, where
// the kernel lets an unprivileged process do it, enters user, mount and network namespaces of its
// own whose root is an empty, private tmpfs holding the staging folder alone, bound read-only at
// its own absolute path: every other path does not exist there, for every system call, and the
// child has no network interface but a loopback that is down. The paths gmsh is given (and names
// in its messages) are unchanged.
//
// Where the kernel refuses the namespaces (before 3.8, or unprivileged user namespaces disabled:
// a sysctl, a container's seccomp profile), nothing changes here; the seccomp filter of
// core/mesh/meshing_child.h still refuses every stat-like call on a path, and Landlock still
// decides the opens (docs/security.md says which box a machine gets).
#include <string>

namespace thinlayer {

// Whether this kernel gives an unprivileged process user, mount and network namespaces (probed
// once, by a short-lived child of this process).
bool private_root_available();

// In a process with one thread (the forked meshing child): makes `folder` (absolute, lexically
// normal) the only thing in its file system, as above, and its working directory. Returns false,
// having changed nothing, where the kernel refuses the namespaces; throws std::runtime_error when
// it refused a later step (the caller must then not run gmsh: the process is half confined).
bool enter_private_root(const std::string& folder);

}  // namespace thinlayer
