#pragma once
// Command-line options shared by `solve` and the studies: the bar's mesh and the solvers.
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "cases/bar/bar.h"
#include "core/solvers/solve_report.h"
#include "core/solvers/solver_choice.h"
#include "studies/cli/command_solve.h"

namespace thinlayer {

// Declares --nx, --ny, --element, --diagonal, --plane, --distortion, --load-scale (group
// "Bar") and --tolerance, --max-iterations, --omega (group "Solvers") on `command`.
void declare_bar_mesh_options(CLI::App& command, SolveArgs& args);
void declare_solver_options(CLI::App& command, SolveArgs& args);

inline const std::set<std::string> bar_mesh_options = {"nx", "ny", "element", "diagonal", "plane", "distortion", "load-scale"};
inline const std::set<std::string> solver_options = {"tolerance", "max-iterations", "omega"};

// What every solve reads besides its scene: the solver, where the results go, how they print.
struct SolveRun {
  SolverKind solver = SolverKind::Fast;
  SolverOptions options;
  std::string out, vtu;
  bool json = false, force = false;
};
// --solver, the solver options, --verbose, --out, --vtu (not the same file), --json, --force.
void parse_solve_run(const CLI::App& command, const SolveArgs& args, SolveRun& run);

bar::MeshOptions parse_bar_mesh(const CLI::App& command, const SolveArgs& args);
SolverOptions parse_solver_options(const CLI::App& command, const SolveArgs& args);
// --friction-path "F1,F2,...": Coulomb coefficients (finite, >= 0) -> their multiples of the
// scene's f, as SolverOptions::friction_path takes them. The scene's f must be > 0.
std::vector<double> friction_path_multipliers(const std::vector<double>& path, double friction);

}  // namespace thinlayer
