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
  double proximal_weight = 1e-2;   // fast only, floating bodies: α of the proximal steps (see fast_solver.cpp)
};

}  // namespace thinlayer
