#pragma once
// `thinlayer study NAME ...` and `thinlayer verify ...`, their options declared here in CLI11.
#include <string>

#include <CLI/CLI.hpp>

#include "studies/cli/command_line.h"

namespace thinlayer {

// The values of the study options as CLI11 converted them (whether each was given: given()).
struct StudyArgs {
  std::string name, out, cases, scene;
  NumberList eps, rate_eps, friction_path;
  NumberList thickness_ratios, modulus_ratios, poisson;  // the validity map's grid
  NumberList refine;          // study convergence --refine: the mesh refinements r (h / r along S)
  double scene_cap = 0;       // --refine: each scene's wall-time cap, s
  std::string resolve;        // --refine: which stored scenes are solved again
  double tolerance = 0, mesh_timeout = 0;
  double peak_distance = 0;  // scene studies: d of the peaks judged at a distance from the bondline ends (mm)
  int repeats = 0, relaxation_cap = 0, threads = 0, bisection_steps = 0;
  long long max_nodes = 0;
  bool quick = false, quiet = false, force = false;
};

// Declare the subcommands `study` (with its positional NAME) and `verify` of `thinlayer`.
CLI::App* declare_study(CLI::App& thinlayer, StudyArgs& args);
CLI::App* declare_verify(CLI::App& thinlayer, StudyArgs& args);

// Run the parsed command. Return the process exit status.
int command_study(const CLI::App& command, const StudyArgs& args);
int command_verify(const CLI::App& command, const StudyArgs& args);

}  // namespace thinlayer
