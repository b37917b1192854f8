#pragma once
// What `thinlayer study` does around its studies when it runs as K MPI ranks (SPEC §6): every
// rank runs the study, rank 0 alone writes the results file, all ranks end with rank 0's exit
// status, and an error that only some ranks met stops all of them instead of leaving the
// others waiting. With one process each of these is what the command did before.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

// Runs `run` on rank 0 alone (the writing of an output). Every rank learns whether it threw, and
// then throws too: the exception itself in one process, ErrorOnEveryRank with its message under
// K ranks, so that an output rank 0 may not write (SPEC §4: exit status 2) stops every rank at
// the same point and is reported once. Every rank must call it.
void on_root(const std::function<void()>& run);

// open_results(dir) on rank 0 (through on_root), with the root attribute `ranks` (K, 1 for one
// process); null on the other ranks (and for an empty dir).
std::unique_ptr<H5Writer> open_results_on_root(const std::string& dir, const OutputRules& rules = {});

// A study that is not spread (the timing study measures time; docs/studies.md, "Studies over MPI
// ranks", for the others):
// rank 0 runs it while the other ranks wait, idle, and return no checks. `why` ends the
// message that says so.
std::vector<Check> on_root_alone(const std::string& study, const std::string& why,
                                 const std::function<std::vector<Check>()>& run);

// Rank 0's exit status, on every rank.
int command_status(int status);

// Reports an error of `thinlayer COMMAND` and returns exit status 2. An ErrorOnEveryRank (a
// scene's failure, studies/parallel/scene_batch.h; an output rank 0 refused) is met by every rank alike
// and printed once; any other error under K > 1
// ranks may be this rank's alone, so it stops every rank (MPI_Abort, status 2).
int command_failed(const std::string& command, const std::exception& e);

}  // namespace thinlayer
