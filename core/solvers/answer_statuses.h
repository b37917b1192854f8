#pragma once
// The statuses an answer stands on, as the active-set methods name them (core/solvers/active_set.h):
// what one more linear solve about that answer must keep (SPEC §3 S6: the first-order layer's
// response is solved on the limit mode's own statuses, MixedSystem::solve_again).
#include <vector>

#include <Eigen/Core>

#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {

// Node by node, from the interface forces r (r_N, r_T per node, daN) and the laws, with the SPEC
// §1.2 classification (classify_statuses, relative tolerance `tolerance`): a bilateral law's node is
// Bonded where its law carries a force (else Gap, as bonded_statuses); a gap node Gap; a node whose
// law has no tangential interaction (K_T = 0 or f = 0) and carries a normal force Frictionless; a
// slide SlidePositive where r_T > 0 (r_T + f r_N = 0), SlideNegative where r_T < 0; else Stick.
std::vector<Active> answer_statuses(const ContactProblem& problem, const Eigen::VectorXd& r, double tolerance);

}  // namespace thinlayer
