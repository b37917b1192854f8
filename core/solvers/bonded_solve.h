#pragma once
// A scene bonded on every face is linear (SPEC §1.6). A bilateral law's status does not depend on
// the iterate — d = 0 on each row that carries a force, for either sign of r; r = 0 on a row that
// carries none — so the statuses are known before the first step, and one sparse solve of the
// whole mixed system for them (core/solvers/mixed_system.h) is the answer. Nothing is condensed:
// its cost is one LU of the mesh's stiffness bordered by the interface rows, which grows as a
// linear solve does, where the condensation forms a dense operator on the interface (time ~ n³ in
// its n nodes). This is the fast solver's path for such scenes (solve_fast takes it by itself).
#include <vector>

#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/mixed_system.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// Is every interface law bilateral (and the problem therefore linear)? False with no interface.
bool every_interface_bonded(const ContactProblem& problem);

// The statuses of a bonded problem: Bonded where the law carries a force, Gap where it carries none.
std::vector<Active> bonded_statuses(const ContactProblem& problem);

// One sparse solve; the report says converged, singular (a body held by nothing), or why the
// residual stays above the tolerance (round-off floor or loss of accuracy). Requires
// every_interface_bonded(problem).
// `factored`: a MixedSystem of this problem to solve with, left factored for another right-hand
// side (MixedSystem::solve_again: SPEC §3 S6's estimate, one more substitution); null: a local one.
SolveReport solve_bonded(const ContactProblem& problem, const SolverOptions& options = {},
                         MixedSystem* factored = nullptr);

}  // namespace thinlayer
