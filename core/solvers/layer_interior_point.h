#pragma once
// The layer mode by a primal-dual interior-point method on the Tresca problem, the Coulomb
// thresholds following the iterates, and a crossover to the exact answer of its statuses.
//
// With the thresholds s frozen the layer problem is the convex quadratic program
//   min ½ yᵀK_y y − F_yᵀ y + Σ_friction s_j τ_j
//   s.t. d_i ≤ 0 (each obstacle row: Signorini), −τ_j ≤ d_j ≤ τ_j (each friction row), d_e = 0 (bonded)
// with d = B_y y + g_D (core/solvers/descent_blocks.h's energy, its |d_T| written through τ).
// Each iteration is one sparse factorisation of
//   [ K_y + B_Iᵀ Θ B_I   B_Eᵀ ] [Δy]
//   [ B_E                0   ] [Δν] = …,
// Θ the barrier's curvature of each inequality row (an obstacle row's z/w; a friction row's
// 4 D⁺D⁻/(D⁺ + D⁻) once its τ is eliminated), Mehrotra's predictor and corrector on the one factor.
//
// Why this method for the layer (issue 40's gate): the layer's film is held by nothing but its two
// contacts; where it is open or slides on both faces its position is decided by its membrane,
// 1e-4 … 1e-16 of the adherents' stiffness, or not at all (SPEC §1.5, non-unique layers). An
// active-set or descent method must decide each of those rows at the film's scale and moves its
// decisions a few rows per step (the TNNMG of core/solvers/tnnmg.h, measured: a film region that
// sags onto a face peels one column per step). A path-following method decides no row until the
// end: every row is weighted by its barrier, the iterates follow the central path to the optimal
// face, and where the answer is not unique they converge to its analytic centre — a selection the
// problem's own geometry makes, no spring. Its iteration count does not grow with the mesh in the
// classical theory (O(√n log 1/ε) as a bound, 20–40 in practice).
//
// Coulomb: s_j = f_j z_N(j) from the current normal multipliers at every iteration (they converge
// with the path). Crossover: where the statuses that the iterate's natural map reads stop changing,
// they are solved exactly on the whole mixed system with Coulomb's slide rows (MixedSystem, one
// sparse LU) and re-read from that answer (semismooth Newton steps) until they reproduce themselves;
// every answer is judged on the SPEC residual of the true problem, the best one kept.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

struct InteriorPointOptions {
  int max_factorisations = 40;        // interior-point iterations and crossover solves together
  Eigen::VectorXd tresca_thresholds;  // Tresca only (one per node, force unit); empty: Coulomb
  // The start: y in MixedSystem's unknowns, and interface forces r (the thresholds and the
  // multipliers' scale). Empty: the bonded start (every row at its kink, one sparse LU).
  Eigen::VectorXd start_y, start_r;
  int centrality_correctors = 2;      // Gondzio's, per iteration (solves on the iteration's factor)
  bool smoothed_crossover = false;    // crossover statuses from the block smoother (else Tapia's reading)
  bool centred_start = false;         // raise the start's products to their mean
  double hybrid_margin = 0;           // the hybrid crossover's margin Q (0: none)
  bool newton_crossover = true;       // the exact crossover of Tapia's statuses and its Newton steps
  double stop_at_iterate_residual = 0;  // > 0: stop once the iterate's SPEC residual is below it
  bool verbose = false;
};

struct InteriorPointRun {
  SolveReport report;                 // the best answer met (crossover answers)
  int factorisations = 0;
  int iterations = 0;                 // interior-point iterations
  int crossovers = 0;                 // exact solves of guessed statuses
  bool applies = true;
  std::string why_not;
  Eigen::VectorXd last_y, last_r;     // the last interior iterate (a warm start for another method)
  double last_residual = 0;           // its SPEC residual
};

// Does the method apply: a layer band, and every interface row rigid or free (descent_blocks.h).
bool layer_interior_point_applies(const ContactProblem& problem);

InteriorPointRun solve_layer_interior_point(const ContactProblem& problem, const SolverOptions& options,
                                            const InteriorPointOptions& ipm = {});

}  // namespace thinlayer
