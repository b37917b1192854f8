#pragma once
// Continuation in the Coulomb coefficient, along a path the caller chooses: solve the scene
// with every friction coefficient multiplied by t₁, then t₂, …, each solve warm started from
// the one before, and last the scene itself (t = 1), which alone decides convergence.
//
// Why it exists: a floating film pinched at the friction limit (the dovetail's case (e) at
// ε = 1e-4, f = 0.5) can defeat the fast solver's path from rest, while a path through smaller
// f (t = 0 is frictionless, hence convex) reaches the tolerance. Which path works is found by
// trying, not known in advance, so it is an option (SolverOptions::friction_path), never a
// default (docs/commands.md has the dovetail's example).
#include <vector>

#include "core/solvers/condensed_interface.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// The same bulk and interfaces with every Coulomb coefficient multiplied by t ≥ 0 (finite).
// The condensation does not depend on the law, so one CondensedInterface serves every t.
ContactProblem with_friction_scaled(const ContactProblem& problem, double t);

// Runs the fast solver along options.friction_path, then on the problem itself. The report is
// the last solve's, with the iterations and wall time of every stage, and the path in its
// message. Throws std::invalid_argument on a multiplier that is negative, NaN or infinite.
SolveReport solve_fast_along_friction_path(const ContactProblem& problem, const CondensedInterface& condensed,
                                           const SolverOptions& options);

}  // namespace thinlayer
