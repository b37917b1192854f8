#pragma once
// `thinlayer solve`: one scene of the bar or the dovetail (--case), or of a scene file
// (--scene, studies/cli/command_scene.h). Its options are declared here, in CLI11.
#include <string>

#include <CLI/CLI.hpp>

#include "studies/cli/command_line.h"

namespace thinlayer {

// The values of solve's options as CLI11 converted them; whether each was given is asked of
// the command (given()), so the defaults stay where they are defined (the cases, the solvers).
struct SolveArgs {
  std::string case_name, mode, law_case, solver, out, vtu, element, diagonal, plane, scene;
  double eps = 0, lambda_bar = 0, mu_bar = 0, friction = 0, scale = 0, gamma = 0, delta = 0, h_interface = 0,
         h_far = 0, distortion = 0, load_scale = 0, tolerance = 0, omega = 0, mesh_timeout = 0;
  int row = 0, nx = 0, ny = 0, layer_elements = 0, max_iterations = 0;
  long long max_nodes = 0;
  NumberList friction_path;
  bool json = false, verbose = false, force = false;
};

// Declares the subcommand `solve` of `thinlayer`, its options bound to `args`.
CLI::App* declare_solve(CLI::App& thinlayer, SolveArgs& args);

// Runs the parsed command. Returns the process exit status.
int command_solve(const CLI::App& command, const SolveArgs& args);

}  // namespace thinlayer
