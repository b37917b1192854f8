#pragma once
// The floating-layer solver (thin-layer mode, SPEC §1.5): the layer eliminated into its dual
// operator, the statuses found on that limit-mode-like problem, the answer from an exact solve
// of those statuses on the true problem.
//
// The layer's condensed face stiffness S (w its face DOFs) is singular: 3 rigid modes, and a
// film of thickness ε has bending modes far below round-off (stiffness ~ μ_ε ε³). Those modes
// are the layer's non-uniqueness (SPEC §1.5: where it is not pinched, its position is not
// unique). With S = V Λ Vᵀ, floor the eigenvalues at ρ = ρ_rel λ_max, so that the soft modes
// get a spring ρ towards an anchor w_a (a selection term, PPA-like), and eliminate w:
//   w(r) = V Λ_ρ⁻¹ (Vᵀ (f_L + B_Lᵀ r) + (Λ_ρ - Λ) Vᵀ w_a),
//   d   = g̃ + W̃ r,   W̃ = W + B_L V Λ_ρ⁻¹ Vᵀ B_Lᵀ  (SPD),   g̃ = g₀ + B_L V Λ_ρ⁻¹ (…).
// Then, per outer step:
//   1. statuses on (W̃, g̃): the limit mode's active-set Newton method, with κ = 1 / W̃_ii, and
//      NSGS sweeps when the active set cycles;
//   2. the polish: those statuses solved exactly on the true (r, w) system (one linear solve);
//   3. the true SPEC residual (per body): done if it meets the tolerance, else the anchor moves
//      to the current w and the next outer step starts from there.
// The selection never enters the answer: convergence is judged on the unregularised residual.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/active_set.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

struct FloatingLayerRun {
  Eigen::VectorXd r, w;
  std::vector<Active> statuses;
  int newton_steps = 0;   // active-set steps and polishes: one linear solve each
  int outer_steps = 0;    // anchor updates (dual) or proximal steps (proximal_layer.h)
  int nsgs_sweeps = 0;
  bool singular = false;  // the last polish's system was rank deficient (the film's position free)
  double rcond = 1;
  double residual = 0;    // the true SPEC residual of (r, w): the best iterate met is returned
  bool stagnated = false; // stopped because the best residual no longer improved (stagnation.h)
};

// options.tolerance decides convergence; at most max_steps Newton steps.
FloatingLayerRun solve_floating_layer(const Condensed& c, const ContactProblem& problem,
                                      const CondensedInterface& condensed, const SolverOptions& options,
                                      Eigen::VectorXd r, Eigen::VectorXd w, int max_steps);

}  // namespace thinlayer
