#pragma once
// The processes a run is spread over (SPEC §6): K MPI ranks under `mpirun -n K` or `srun`,
// or one process. The only file that sees MPI.
//
// MPI is started only when a launcher started us (its environment variables say so), so a
// plain `thinlayer ...` never loads MPI's machinery, never waits for peers and prints nothing
// of MPI's. Every rank runs the same study code on the same inputs (SPMD); what differs is
// which scenes each solves (studies/parallel/scene_batch.h) and that only rank 0 prints tables and
// writes files: the other ranks' stdout goes to /dev/null (their progress lines on stderr
// stay, prefixed with their rank).
#include <stdexcept>
#include <string>
#include <vector>

namespace thinlayer {

// One per process, in main(): starts MPI if launched by mpirun/srun, stops it on destruction.
class ProcessGroup {
 public:
  ProcessGroup(int& argc, char**& argv);
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;
};

int rank();         // 0 in a one-process run
int rank_count();   // K; 1 in a one-process run
inline bool is_root() { return rank() == 0; }

// Every rank contributes `mine`; every rank receives all ranks' contributions, by rank.
std::vector<std::string> all_gather(const std::string& mine);

// Rank 0's value, on every rank.
int broadcast_from_root(int value);

// While one of these lives, this process works alone (rank 0 in on_root_alone): scene batches
// then solve everything here instead of waiting for ranks that are not running the study.
class WorkingAlone {
 public:
  WorkingAlone();
  ~WorkingAlone();
  WorkingAlone(const WorkingAlone&) = delete;
  WorkingAlone& operator=(const WorkingAlone&) = delete;
};
// The ranks a scene batch spreads over: rank_count(), or 1 while working alone.
int spread_ranks();
int spread_rank();

// Rank 0 works alone (the timing study) while the others wait without spinning a core: they
// call this and return when rank 0 calls it too.
void wait_for_each_other();

// An error that every rank meets at the same point of the run and knows of (a scene that failed,
// studies/parallel/scene_batch.h; an output rank 0 cannot write): rank 0 reports it, once, and every rank
// ends with exit status 2 without MPI_Abort.
struct ErrorOnEveryRank : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Stops every rank at once, with this exit status: for an error that only some ranks met,
// whose peers would otherwise wait for them forever.
[[noreturn]] void abort_all_ranks(int status);

// Under K > 1 ranks, commands that are not spread say so and refuse (exit 2): true if the
// command may run.
bool refuse_unless_one_process(const std::string& command);

}  // namespace thinlayer
