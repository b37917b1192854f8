#pragma once
// The floating-layer solver (thin-layer mode, SPEC §1.5; issue 13).
//
// The layer is held by nothing but its two contacts, and where it is not pinched its position
// is not unique (a free film, a slip that may sit on either face). Its condensed stiffness S on
// x (core/solvers/floating_condensation.h: per column the minus face's translation t and the
// plus face's displacement relative to it) is accurate, but its translations are held only by
// the film's in-plane stiffness, down to 1e-13 of its through-thickness stiffness. A selection
// spring ρ P (P: core/solvers/floating_condensation.h) holds them towards the layer's rest
// position, and the problem is solved as ρ decreases:
//   1. ρ = κ·10⁰, 10⁻², …, 10⁻⁸ (κ the adherents' nodal stiffness): the layer is eliminated,
//      d = g̃ + W̃ r with W̃ = W + B_L (S + ρP)⁻¹ B_Lᵀ (core/solvers/layer_dual.h), and the
//      statuses are found there by the active-set method warm started from the previous ρ; where
//      it cycles, by the Tresca fixed point (core/solvers/tresca.h), which cannot;
//   2. ρ = κ·10⁻¹⁰, 10⁻¹², 10⁻¹⁴: W̃ is too ill-conditioned to solve in (its film compliance 1/ρ hides
//      the adherents' by 12 orders), so the Newton steps solve the mixed (r, x) system instead,
//      with the statuses still guessed on W̃'s scale (κ_row = 1/W̃_ii: decided by the forces on
//      a film that the slightest force moves far, not by its jumps);
//   3. the spring's pull ρ P (x − anchor) is part of the answer's error: the anchor moves to the
//      layer (a proximal step), Anderson-accelerated, each step re-settling the statuses, until
//      the true residual meets the tolerance (a film pushed along by a force nothing else resists
//      goes where that force is balanced, however far).
// The selection never enters the verdict: every candidate is judged on the true, per-body SPEC
// residual, and the best one met is returned.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/active_set.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

struct FloatingLayerRun {
  Eigen::VectorXd r, x;
  std::vector<Active> statuses;
  int newton_steps = 0;   // linear solves: active-set steps, Tresca QP steps, mixed steps
  int outer_steps = 0;    // spring stages and proximal steps
  // The best iterate's statuses: whether their system is rank deficient (a layer left free), and
  // its reciprocal condition estimate; with the selection spring if converged, without if not.
  bool singular = false;
  double rcond = 1;
  double residual = 0;    // the true SPEC residual of (r, x), the best met
  bool adrift = false;    // not converged, and the last proximal steps each re-settled the same
                          // statuses: the layer is being followed along a push, not searched for
  bool capped = false;    // SolverOptions::max_iterations ran out (the answer's solve kept back)
};

// c: the scene's condensed problem with its floating unknowns x (S without spring); r, x: the
// starting iterate (a warm start, or zero).
FloatingLayerRun solve_floating_layer(const Condensed& c, const ContactProblem& problem,
                                      const CondensedInterface& condensed, const SolverOptions& options,
                                      Eigen::VectorXd r, Eigen::VectorXd x);

}  // namespace thinlayer
