#pragma once
// The project's default solver (SPEC §1.5): condensation onto the interface, then a
// primal-dual active-set method — a semismooth Newton method on the natural map of the
// Signorini-Coulomb conditions (Alart-Curnier; Hüeber-Stadler-Wohlmuth) — on the small dense
// problem d = g₀ + (W + C) r. Once the statuses are right, one linear solve gives the exact
// answer; if the active set cycles, projected Gauss-Seidel sweeps on the same condensed
// problem (NSGS) move the iterate before the Newton steps resume. With
// SolverOptions::friction_path set, the solve follows that continuation in the Coulomb
// coefficient first (core/solvers/friction_path.h). A scene bonded on every face is linear and
// takes one sparse solve instead (core/solvers/bonded_solve.h).
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

SolveReport solve_fast(const ContactProblem& problem, const CondensedInterface& condensed,
                       const SolverOptions& options = {});

// Whether solve_fast needs the condensation of this problem up front: not where the problem is bonded
// on every face (one sparse solve) nor where a layer takes the interior-point method first (the
// condensation is built only if the ladder has to take over).
bool needs_condensation(const ContactProblem& problem, const SolverOptions& options);

// Convenience: factor and condense, then solve (for one-off scenes).
SolveReport solve_fast(const ContactProblem& problem, const SolverOptions& options = {});

}  // namespace thinlayer
