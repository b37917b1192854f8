#include "studies/parallel/spread_command.h"

#include <iostream>

#include "studies/parallel/process_group.h"
#include "studies/cli/results_file.h"
#include "studies/parallel/scene_batch.h"
#include "studies/tools/run_phase.h"

namespace thinlayer {

void on_root(const std::function<void()>& run) {
  if (rank_count() == 1) return run();
  std::string error;
  if (is_root()) try {
      run();
    } catch (const std::exception& e) {
      error = e.what();
    }
  if (broadcast_from_root(error.empty() ? 0 : 1)) throw ErrorOnEveryRank(error);
}

std::unique_ptr<H5Writer> open_results_on_root(const std::string& dir, const OutputRules& rules) {
  std::unique_ptr<H5Writer> out;
  on_root([&] {
    out = open_results(dir, rules);
    if (out) out->attr("/", "ranks", rank_count());
  });
  return out;
}

std::vector<Check> on_root_alone(const std::string& study, const std::string& why,
                                 const std::function<std::vector<Check>()>& run) {
  if (rank_count() == 1) return run();
  if (is_root())
    std::cerr << "[" << study << "] rank 0 runs it alone while the other " << rank_count() - 1
              << " rank(s) wait: " << why << "\n";
  std::vector<Check> checks;
  if (is_root()) {
    const WorkingAlone alone;
    checks = run();
  }
  wait_for_each_other();
  return checks;
}

int command_status(int status) { return broadcast_from_root(status); }

int command_failed(const std::string& command, const std::exception& e) {
  const bool everyone_knows = dynamic_cast<const ErrorOnEveryRank*>(&e) != nullptr;
  if (rank_count() == 1 || (everyone_knows && is_root())) print_message(command, failure_text(e));
  if (rank_count() == 1 || everyone_knows) return 2;
  print_message(command + " (rank " + std::to_string(rank()) + " of " + std::to_string(rank_count()) + ")", failure_text(e));
  abort_all_ranks(2);
}

}  // namespace thinlayer
