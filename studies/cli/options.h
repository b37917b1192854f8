#pragma once
// Command-line options shared by `solve` and the studies: the bar's mesh and the solvers.
#include <set>
#include <string>

#include "cases/bar/bar.h"
#include "core/solvers/solve_report.h"
#include "studies/cli/args.h"

namespace thinlayer {

#define MESH_AND_SOLVER_HELP \
  "  --nx N, --ny N       elements along AD and DE (default 32 x 32)\n" \
  "  --element E          Q1 (default) | P1\n" \
  "  --diagonal D         P1 only: right (default, '/') | left ('\\')\n" \
  "  --plane P            strain (default) | stress\n" \
  "  --distortion D       bar: move interior nodes by up to D x the element size, 0 <= D < 0.5\n" \
  "                       (a reproducible pseudo-random pattern; stress tests)\n" \
  "  --load-scale S       bar: multiply the tractions F1, F2 by S (-1 lifts the bar off AD)\n" \
  "  --tolerance T        SPEC residual to reach (default 1e-10)\n" \
  "  --max-iterations N   solver iteration cap, N >= 1 (default: fast 200; with a floating layer\n" \
  "                       none, its spring stages bound the work; relaxation 100000 sweeps)\n" \
  "  --omega W            relaxation's over-relaxation coefficient in (0, 2) (default 1.8)\n"

inline const std::set<std::string> mesh_and_solver_options = {"nx", "ny", "element", "diagonal", "plane", "distortion", "load-scale",
                                                              "tolerance", "max-iterations", "omega"};

bar::MeshOptions parse_bar_mesh(const Args& args);
SolverOptions parse_solver_options(const Args& args);
// --friction-path "F1,F2,...": Coulomb coefficients (finite, >= 0) -> their multiples of the
// scene's f, as SolverOptions::friction_path takes them. The scene's f must be > 0.
std::vector<double> friction_path_multipliers(const std::string& text, double friction);

}  // namespace thinlayer
