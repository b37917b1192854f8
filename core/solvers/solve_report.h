#pragma once
// What every solve returns (SPEC §1.5): the solution, how it was reached, and how well.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"
#include "core/solvers/floating_condensation.h"

namespace thinlayer {

// Why a solve stopped. Every solve that does not converge names one of these (SPEC §1.5; the
// stress tests of S5 check that none stops without a cause).
enum class StopCause {
  Converged,       // the SPEC residual reached the tolerance, with a unique answer
  IterationCap,    // the iteration cap was reached first
  Singular,        // the answer is not unique: a floating body is held by none of its contacts
  LossOfAccuracy,  // the statuses settled but the linear solve could not reach the tolerance
  RoundOffFloor,   // the residual, evaluated in extended precision, is within what rounding this
                   // answer to double moves it by (Residual::floor(), bodies and interfaces), which
                   // lies above the tolerance; a residual above its floor is a stall (another cause)
  LayerAdrift,     // a floating layer is pushed by a force only the selection spring resists
                   // (core/solvers/floating_layer.h): its exact position is beyond the proximal steps
  NonFinite,       // NaN or Inf appeared in the iterate
};
const char* to_string(StopCause cause);

struct SolveReport {
  std::string solver;           // "fast" | "relaxation"
  // Which of the fast solver's methods gave the answer: "bonded solve", "sparse Newton",
  // "condensed active set", "floating-layer ladder"; "A after B" where B stopped and A took over.
  std::string method;
  Eigen::VectorXd u;            // free DOFs, mm
  Eigen::VectorXd r;            // interface forces (r_N, r_T) per node, daN per unit thickness
  Eigen::VectorXd w;            // fast solver: the floating bodies' interface DOFs, mm (empty if none)
  int iterations = 0;           // fast: active-set (Newton) steps; relaxation: Gauss-Seidel sweeps
  Residual residual;            // SPEC §1.5, evaluated on (u, r) by contact_residual()
  double tolerance = 0;         // the residual the solve aimed for
  bool converged = false;
  StopCause stop_cause = StopCause::IterationCap;
  // An estimate of the condition number of the linear systems the solver solved (fast: the
  // larger of 1 / LAPACK-style rcond of the equilibrated final active-set matrix and 1 / CHOLMOD's
  // rcond of the bulk factors; capped at 1e300); 0 when not estimated (relaxation).
  // Round-off limits the attainable residual to about 1e-16 times it.
  double condition_estimate = 0;
  double wall_time_s = 0;       // the solve alone (factorisation reported separately)
  std::string message;          // why it stopped, in one line
};

// Which method solves a problem with a layer band (the thin-layer mode). InteriorPoint: the primal-dual
// interior-point method of core/solvers/layer_interior_point.h, the floating-layer ladder
// (core/solvers/floating_layer.h) taking over where it stops short; Ladder: the ladder alone.
enum class LayerMethod { InteriorPoint, Ladder };

struct SolverOptions {
  double tolerance = 1e-10;     // on Residual::value()
  int max_iterations = 0;       // 0: the solver's default
  double omega = 1.8;           // relaxation only: over-relaxation coefficient ω
  int sweeps_per_rho_update = 10;  // relaxation only: sweeps between friction-threshold updates
  bool verbose = false;         // progress lines on stderr
  // Fast solver, floating layer only: which face of the layer the selection spring holds where
  // the layer's position is not unique (core/solvers/floating_layer.h). Both selections are
  // answers; they must agree on what the problem determines (SPEC §1.5).
  LayerSelection layer_selection = LayerSelection::MinusFace;
  // Fast solver only: the complementarity parameter of the active-set guess, relative to the
  // nodal stiffness. It changes the path, never the answer (judged on the SPEC residual). On
  // the bar's layer mode (6 rows × ε = 1e-2, 1e-3, 1e-4) 1 converged in 14 of 18 scenes, 0.1 in
  // 15, 0.01 and 0.001 in all 18; limit-mode scenes converge the same with any of them.
  double complementarity_scale = 0.01;
  // Fast solver only: a warm start — interface forces r and floating-body DOFs w of a nearby
  // solution (a previous law on the same bulk, the previous ε of a sweep). Empty: from rest.
  // The first active set is guessed from them; with the right statuses the solve is a single
  // linear solve.
  Eigen::VectorXd initial_r, initial_w;
  // Fast solver only: leave out the tangential rows of nodes whose law has no tangential
  // interaction (K_T = 0 or f = 0: cases a, c, e). Off only to measure what it saves.
  bool skip_frictionless_rows = true;
  // Fast solver only: multipliers t of every Coulomb coefficient to solve for first, in order,
  // each solve warm started from the one before; the scene itself (t = 1) comes last and alone
  // decides convergence (core/solvers/friction_path.h). Empty (the default): none.
  std::vector<double> friction_path;
  // Fast solver only: a body held by contact and friction alone and no layer band takes the sparse
  // Newton first (core/solvers/sparse_newton.h). Off only to measure the condensed path against it.
  bool sparse_newton = true;
  // Fast solver only: the method of a problem with a layer band (LayerMethod above).
  LayerMethod layer_method = LayerMethod::InteriorPoint;
};

}  // namespace thinlayer
