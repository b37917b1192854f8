#pragma once
// gmsh run on a user's files, in a child process in a box with a clock, whose failures are the
// parent's error messages, not its crash (SPEC §4).
//
// Why a child: gmsh reads a user's .geo as a program, and fails in ways a caller cannot catch.
// Some of its errors are thrown inside its OpenMP regions, where an exception ends the process
// (std::terminate, exit 134: a mesh size of 1e-9, a .geo ending in "Mesh 2;"); some meshing
// algorithms crash outright (Mesh.Algorithm = 8 in Debian's gmsh 4.8, exit 139); a loop in a
// .geo can run for ever, a damaged .msh can take the reader down. In a child each of these ends
// the child, and the parent says what happened, and in which phase, in one line.
//
// The child (fork of this process, so it needs no new program and shares the parent's gmsh
// state as it was):
//   - has stdin, stdout and stderr on /dev/null (gmsh's own printing never reaches the user's
//     terminal or the JSON line of `solve --json`) and no other file descriptor but its pipe;
//   - has an empty environment (PWD alone, the staging folder: what gmsh reads after it started);
//   - works in `read_folder` (the private staging folder of cases/scene/scene_sources.h), which is
//     all its file system holds where the kernel gives it namespaces (core/mesh/private_root.h),
//     and may read nothing else: Landlock where the kernel has it (core/mesh/read_box.h);
//   - makes only the system calls of an allow-list (a seccomp filter, libseccomp; every other
//     call fails with EPERM): no program run, no process started, no file opened for writing,
//     created, removed, renamed or linked, no stat of a path, no socket, no signal to another
//     process, no executable memory;
//   - has at most `memory_limit_bytes` of address space (or the lower limit it inherited: that
//     one is named), `cpu_limit_s` of CPU time, no core dump, and of wall clock what is left of
//     the command's (set_meshing_wall_clock; a Sleep or a read that waits uses no CPU) or
//     `wall_limit_s` if less: past it the parent kills it;
//   - dies with its parent (PR_SET_PDEATHSIG), and with a SIGINT or SIGTERM of the parent
//     (forwarded by core/io/output_target.h's handler).
// The work names its phases (meshing_phase): a crash, the clock or the memory limit is reported
// with the phase it ended ("... while estimating the mesh's size").
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace thinlayer {

// A failure of the work done in the child, as one line (no file named: the caller knows it).
// `input` is true when the work threw an error about its input (InputError or
// std::invalid_argument), false for anything else (gmsh's own errors, a crash, a limit).
struct MeshingChildError : std::runtime_error {
  MeshingChildError(const std::string& what, bool input) : std::runtime_error(what), input(input) {}
  bool input;
};

struct MeshingChildLimits {
  long long memory_limit_bytes = 8LL << 30;  // 8 GiB: a 2e6-node mesh takes about 2 GiB in gmsh
  long long cpu_limit_s = 600;
  double wall_limit_s = std::numeric_limits<double>::infinity();  // this run's own bound; the command's clock bounds all runs
  std::string read_folder;    // the only folder the child may read, and its working directory ("": no read box)
};

// Runs `work` in the child and returns the bytes it returns. Throws MeshingChildError with
// `work`'s exception message, or saying how the child ended (a signal, a limit, the clock, an
// exit without an answer) and in which phase. The gmsh lock (gmsh_session.h) is held across the
// fork, so no other thread of this process is inside gmsh then; `work` itself must not take it.
std::string run_in_meshing_child(const std::function<std::string()>& work, const MeshingChildLimits& limits = {});

// One wall clock for all the meshing of a command (SPEC §4; --mesh-timeout, default 600 s): each
// run_in_meshing_child draws the child's wall time from it, and is stopped when it runs out (a
// scene study meshes its geometry 4 times: together they stay within the limit, not each).
// Children run side by side by threads each count their own time. A run that finds it spent
// throws at once. Setting it starts it again, full.
constexpr double default_mesh_timeout_s = 600;
void set_meshing_wall_clock(double seconds);

// In the child: the phase the work enters ("reading the geometry", "meshing", ...), told to the
// parent at once. Outside a meshing child: nothing.
void meshing_phase(const std::string& phase);

// In the child: runs `step` (in `phase`) within a bound of its own, tighter than the child's:
// at most `memory_bytes` more address space and `seconds` of wall clock. Beyond either, the
// child answers `why` as an input error and ends. Outside a meshing child: just runs `step`.
void run_bounded(const std::string& phase, long long memory_bytes, unsigned seconds, const std::string& why,
                 const std::function<void()>& step);

}  // namespace thinlayer
