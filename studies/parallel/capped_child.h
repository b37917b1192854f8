#pragma once
// One piece of work under a wall-clock cap, in a process of its own: a scene that runs past its cap
// is stopped at the cap (the solver need not know of any clock), and one that crashes takes only its
// process down. The study that asks records what happened and carries on.
//
// The worker is a fresh run of a program (thinlayer itself, with a hidden command), not a fork of
// the caller: a fork would inherit the caller's library state, and one that has run OpenMP code
// (CHOLMOD's supernodal factorisation on gmsh's thread count) hangs in the child at its next parallel
// region, its thread pool gone. So the worker rebuilds what it needs from the input it is given.
//   - its standard input: the input bytes; its standard output: the answer (the worker's own stdout
//     printing is sent to its stderr by serve_capped); its stderr: the caller's;
//   - its environment: the caller's without MPI's and the launcher's variables (OMPI_*, PMIX_*,
//     PMI_*, SLURM_*), so that it runs as one process and never joins the caller's MPI job;
//   - it dies with its caller (PR_SET_PDEATHSIG) and with a SIGINT or SIGTERM of the caller
//     (forwarded by core/io/output_target.h's handler).
#include <functional>
#include <string>
#include <vector>

namespace thinlayer {

struct CappedRun {
  enum class Ending {
    Answered,     // the work returned: `answer` holds its bytes
    Capped,       // the cap ran out: the worker was killed
    Threw,        // the work threw: `message` holds what
    Crashed,      // the worker ended without an answer (a signal, an exit): `message` says how
    Interrupted,  // the worker was stopped by SIGINT, SIGTERM or SIGHUP from outside: no outcome of the work
  };
  Ending ending = Ending::Crashed;
  std::string answer;
  std::string message;
  double seconds = 0;      // wall clock, from the start to the worker's end
  double cpu_seconds = 0;  // the worker's CPU time (user and system, its own children included): on a
                           // shared machine the wall clock says how loaded it was, this what the work took
};

// Runs `command` (command[0] the program's path) with `input` on its standard input, waits at most
// `wall_limit_s` seconds for its answer, and says how it ended. Throws std::runtime_error only when
// no process can be started.
CappedRun run_capped(const std::vector<std::string>& command, const std::string& input, double wall_limit_s);

// The worker's side: reads all of its standard input, runs `work` on it with standard output sent
// to standard error, and writes the answer (`work`'s bytes, or what it threw) to the real standard
// output. Returns the process's exit status (0).
int serve_capped(const std::function<std::string(const std::string&)>& work);

// This program's own path (/proc/self/exe), to start a worker of it.
std::string this_program();

const char* to_string(CappedRun::Ending ending);

}  // namespace thinlayer
