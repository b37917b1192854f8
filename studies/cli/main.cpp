// thinlayer: verification and benchmark suite for thin adhesive layers in frictional contact
// and their limit interface laws (Lebon & Zaittouni 2010).
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/io/output_target.h"
#include "core/io/shown_text.h"
#include "studies/tools/run_phase.h"
#include "studies/cli/command_line.h"
#include "studies/cli/command_solve.h"
#include "studies/cli/command_study.h"
#include "studies/cli/environment.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/refinement_scenes.h"
#include "studies/parallel/process_group.h"

namespace {

// The command line, declared in CLI11 (studies/cli/command_line.h): the commands are its
// subcommands, each with its options and its help.
struct Thinlayer {
  CLI::App app{"", "thinlayer"};
  thinlayer::SolveArgs solve_args;
  thinlayer::StudyArgs study_args;
  CLI::App* solve = nullptr;
  CLI::App* study = nullptr;
  CLI::App* verify = nullptr;

  Thinlayer() {
    app.formatter(thinlayer::help_formatter("usage: thinlayer COMMAND [options]\n       thinlayer --version"));
    app.set_help_flag("-h,--help", "this help");
    solve = thinlayer::declare_solve(app, solve_args);
    study = thinlayer::declare_study(app, study_args);
    verify = thinlayer::declare_verify(app, study_args);
    for (CLI::App* command : {solve, study, verify}) command->group("Commands");
    app.footer("Each command's options: thinlayer COMMAND --help.\n"
               "Units: mm and daN (stresses in daN/mm^2 = 10 MPa; lambda_bar, mu_bar in daN/mm^3).");
  }

  std::string main_help() const { return app.help(); }

  // The command called `name`, or null.
  CLI::App* command_named(const std::string& name) {
    for (CLI::App* command : {solve, study, verify})
      if (command->get_name() == name) return command;
    return nullptr;
  }

  int run(const std::string& name, const std::vector<std::string>& args) {
    CLI::App* command = command_named(name);
    try {
      thinlayer::parse_command(*command, args);
    } catch (const CLI::CallForHelp&) {
      std::fputs(command->help().c_str(), stdout);
      return 0;
    } catch (const std::exception& e) {
      // Under mpirun every rank parsed the same arguments: one says so.
      if (thinlayer::is_root()) thinlayer::print_message(name, e.what());
      return 2;
    }
    if (command == solve) return thinlayer::command_solve(*command, solve_args);
    if (command == study) return thinlayer::command_study(*command, study_args);
    return thinlayer::command_verify(*command, study_args);
  }
};

}  // namespace

int main(int argc, char** argv) {
  // An interrupted run removes its temporary files; the previous results stay (SPEC §4). Under
  // mpirun the same handler serves every rank: mpirun turns a Ctrl-C into SIGTERM for each of
  // them, and only rank 0 has a temporary results file to remove. Set before MPI starts.
  thinlayer::install_signal_cleanup();
  thinlayer::ProcessGroup processes(argc, argv);  // MPI under mpirun/srun (SPEC §6)
  std::vector<std::string> args(argv + 1, argv + argc);
  // One scene of `study convergence --refine`, in a worker process of its own (not a user's command).
  if (args.size() == 1 && args[0] == thinlayer::scene_worker_command) return thinlayer::serve_refinement_scene();
  if (args.size() == 1 && args[0] == "--version") {
    std::printf("thinlayer %s (results layout %s version %d; source commit %s)\n", THINLAYER_VERSION,
                thinlayer::results_layout, thinlayer::results_layout_version,
                thinlayer::environment_info().at("commit").c_str());
    return 0;
  }
  Thinlayer thinlayer;
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(thinlayer.main_help().c_str(), stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  if (!thinlayer.command_named(command)) {
    std::cerr << "thinlayer: unknown command '" << thinlayer::shown(command) << "' (see thinlayer --help)\n";
    return 2;
  }
  if ((command == "solve" || command == "verify") && !thinlayer::refuse_unless_one_process(command)) return 2;
  return thinlayer.run(command, args);
}
