// thinlayer: verification and benchmark suite for thin adhesive layers in frictional contact
// and their limit interface laws (Lebon & Zaittouni 2010).
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "core/io/output_target.h"
#include "studies/cli/command_solve.h"
#include "studies/cli/command_study.h"
#include "studies/cli/environment.h"
#include "studies/parallel/process_group.h"
#include "studies/cli/results_file.h"

namespace {

const char* const main_help = R"(usage: thinlayer COMMAND [options]
       thinlayer --version

Commands:
  solve      solve one scene (bar or dovetail, limit or layer mode)   (thinlayer solve --help)
  study      run a study                                              (thinlayer study --help):
               table3, dovetail, convergence, validity, thresholds, asymptotics, timing, stress
  verify     run every study, write the summary and the report        (thinlayer verify --help)

Units: mm and daN (stresses in daN/mm^2 = 10 MPa; lambda_bar, mu_bar in daN/mm^3).
)";

bool wants_help(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  // An interrupted run removes its temporary files; the previous results stay (SPEC §4). Under
  // mpirun the same handler serves every rank: mpirun turns a Ctrl-C into SIGTERM for each of
  // them, and only rank 0 has a temporary results file to remove. Set before MPI starts.
  thinlayer::install_signal_cleanup();
  thinlayer::ProcessGroup processes(argc, argv);  // MPI under mpirun/srun (SPEC §6)
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "--version") {
    std::printf("thinlayer %s (results layout %s version %d; source commit %s)\n", THINLAYER_VERSION,
                thinlayer::results_layout, thinlayer::results_layout_version,
                thinlayer::environment_info().at("commit").c_str());
    return 0;
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(main_help, stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  if ((command == "solve" || command == "verify") && !thinlayer::refuse_unless_one_process(command)) return 2;
  if (command == "solve") {
    if (wants_help(args)) return std::fputs(thinlayer::solve_help, stdout), 0;
    return thinlayer::command_solve(args);
  }
  if (command == "study") {
    if (wants_help(args)) return std::fputs(thinlayer::study_help, stdout), 0;
    return thinlayer::command_study(args);
  }
  if (command == "verify") {
    if (wants_help(args)) return std::fputs(thinlayer::verify_help, stdout), 0;
    return thinlayer::command_verify(args);
  }
  std::cerr << "thinlayer: unknown command '" << command << "' (see thinlayer --help)\n";
  return 2;
}
