#pragma once
// What every solve returns (SPEC §1.5): the solution, how it was reached, and how well.
#include <string>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"

namespace thinlayer {

struct SolveReport {
  std::string solver;           // "fast" | "relaxation"
  Eigen::VectorXd u;            // free DOFs, mm
  Eigen::VectorXd r;            // interface forces (r_N, r_T) per node, daN per unit thickness
  int iterations = 0;           // fast: active-set (Newton) steps; relaxation: Gauss-Seidel sweeps
  Residual residual;            // SPEC §1.5, evaluated on (u, r) by contact_residual()
  double tolerance = 0;         // the residual the solve aimed for
  bool converged = false;
  double wall_time_s = 0;       // the solve alone (factorisation reported separately)
  std::string message;          // why it stopped, in one line
};

struct SolverOptions {
  double tolerance = 1e-10;     // on Residual::value()
  int max_iterations = 0;       // 0: the solver's default
  double omega = 1.8;           // relaxation only: over-relaxation coefficient ω
  int sweeps_per_rho_update = 10;  // relaxation only: sweeps between friction-threshold updates
  bool verbose = false;         // progress lines on stderr
  // Fast solver only. α of the proximal steps taken when a floating body is present, relative
  // to the diagonal of its condensed stiffness (see fast_solver.cpp).
  double proximal_weight = 1e-2;
  // Fast solver only: the complementarity parameter of the active-set guess, relative to the
  // nodal stiffness. It changes the path, never the answer (judged on the SPEC residual). On
  // the bar's layer mode (6 rows × ε = 1e-2, 1e-3, 1e-4) 1 converged in 14 of 18 scenes, 0.1 in
  // 15, 0.01 and 0.001 in all 18; limit-mode scenes converge the same with any of them.
  double complementarity_scale = 0.01;
};

}  // namespace thinlayer
