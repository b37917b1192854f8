#pragma once
// Semismooth Newton on the whole sparse system, from the bonded solve (issue 33): for a problem
// whose floating bodies are held by contact and friction alone and are not layer bands — an
// adherent held by its glue lines in limit mode.
//
// Each step solves the whole mixed system (core/solvers/mixed_system.h: every body, every
// interface row, one UMFPACK factorisation on a fixed pattern) for the current statuses, then
// re-guesses the statuses from the answer's natural map (guess_statuses), until they reproduce
// themselves. Nothing is condensed: the condensed path's dense Delassus operator on a floating
// body's faces and its damped active set took 90–1008 steps on a friction-held double lap
// (202–474 nodes on S, 50–126 s), these steps 5 at either size.
//
// Why the bonded solve is the start: at rest every friction threshold f|r_N| is zero, and the
// first Newton matrix leaves a body that friction holds free to slide (singular). The bonded
// solve — every node stuck, one linear solve — gives every node the normal force of the joint
// glued, so the first re-guess already has the thresholds of the load (GetFEM's generalized
// Newton on the same discrete problem did not converge from rest either, and converged in 3–4
// steps from there; issue 33, finding 6).
#include <vector>

#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// Does this problem take the sparse Newton path: a floating body that is no layer band (a layer's
// film needs the floating-layer solver, core/solvers/floating_layer.h) and an interface that is
// not bonded (a bonded problem is one linear solve, core/solvers/bonded_solve.h)?
bool takes_sparse_newton(const ContactProblem& problem);

// Every node stuck (bilateral nodes bonded; a node whose law carries no tangential force in
// frictionless contact; one whose law carries nothing open): the statuses of the joint glued.
std::vector<Active> stuck_statuses(const ContactProblem& problem);

struct SparseNewtonRun {
  SolveReport report;      // the best answer met, judged on the SPEC residual
  bool settled = false;    // the statuses reproduced themselves
  bool cycled = false;     // a status set met before came back
  bool singular = false;   // a step's statuses left a body free
};

// From `seed` (stuck_statuses by default) at most `max_steps` factorisations.
SparseNewtonRun solve_sparse_newton(const ContactProblem& problem, const SolverOptions& options,
                                    std::vector<Active> seed = {}, int max_steps = 30);

}  // namespace thinlayer
