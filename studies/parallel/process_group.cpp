#include "studies/parallel/process_group.h"

// The C API only: without these, <mpi.h> included from C++ drags in the long-deprecated C++
// bindings, which live in a library we do not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "core/linalg/factor_memory.h"
#include "studies/parallel/blas_threads.h"

namespace thinlayer {

namespace {

int my_rank = 0;
int ranks = 1;
bool mpi_started = false;
int working_alone = 0;

// mpirun (Open MPI) and srun (PMIx or PMI-2) set these in every process they start.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

// Waits for a non-blocking operation by polling it with short sleeps: Open MPI's blocking calls
// spin a core while they wait, which on a shared or oversubscribed machine slows down the
// ranks that still have scenes to solve.
void wait_politely(MPI_Request& request) {
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace

ProcessGroup::ProcessGroup(int& argc, char**& argv) {
  use_one_blas_thread();
  keep_factor_memory();
  if (!launched_by_mpi()) return;
  int provided = 0;
  // Only the main thread calls MPI; the scene threads never do.
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi_started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &my_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  // Rank 0 alone prints the tables.
  if (my_rank != 0 && !std::freopen("/dev/null", "w", stdout)) std::cerr << "rank " << my_rank << ": no /dev/null\n";
}

ProcessGroup::~ProcessGroup() {
  if (!mpi_started) return;
  std::fflush(stdout);
  MPI_Finalize();
}

int rank() { return my_rank; }
int rank_count() { return ranks; }

WorkingAlone::WorkingAlone() { ++working_alone; }
WorkingAlone::~WorkingAlone() { --working_alone; }
int spread_ranks() { return working_alone ? 1 : ranks; }
int spread_rank() { return working_alone ? 0 : my_rank; }

std::vector<std::string> all_gather(const std::string& mine) {
  if (ranks == 1) return {mine};
  if (mine.size() > static_cast<std::size_t>(INT_MAX)) throw std::runtime_error("a rank's results exceed 2 GiB");
  std::vector<int> sizes(ranks);
  int my_size = static_cast<int>(mine.size());
  MPI_Request request;
  MPI_Iallgather(&my_size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD, &request);
  wait_politely(request);
  std::vector<int> offsets(ranks, 0);
  long long total = 0;
  for (int r = 0; r < ranks; ++r) {
    offsets[r] = static_cast<int>(total);
    total += sizes[r];
    if (total > INT_MAX) throw std::runtime_error("the gathered results of one batch exceed 2 GiB");
  }
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Iallgatherv(mine.data(), my_size, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, MPI_COMM_WORLD,
                  &request);
  wait_politely(request);
  std::vector<std::string> out;
  for (int r = 0; r < ranks; ++r) out.push_back(all.substr(offsets[r], sizes[r]));
  return out;
}

int broadcast_from_root(int value) {
  if (ranks == 1) return value;
  MPI_Request request;
  MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  wait_politely(request);
  return value;
}

void wait_for_each_other() {
  if (ranks == 1) return;
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  wait_politely(request);
}

void abort_all_ranks(int status) {
  std::fflush(stdout);
  std::fflush(stderr);
  if (mpi_started) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

bool refuse_unless_one_process(const std::string& command) {
  if (ranks == 1) return true;
  if (my_rank == 0)
    std::cerr << "thinlayer " << command << ": runs as one process only (of the commands, `thinlayer study` spreads "
              << "its scenes over MPI ranks); run it without mpirun/srun\n";
  return false;
}

}  // namespace thinlayer
