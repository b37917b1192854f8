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
// Two safeguards, each derived, not fitted (sparse_newton.cpp): a guess that lets every node of a
// friction-held body slide keeps one stuck (below friction's capacity, which load_path.h checks
// before the solve, the answer has a stuck node; all sliding leaves the body free along its faces),
// and where a step's answer has a larger residual than the iterate, the statuses are guessed from
// the first point towards it whose residual is smaller (backtracking on the SPEC residual). On
// seeded friction-held double laps (scripts/random_friction_joints.py) with unequal clamping
// pressures, plain Newton settled 12 of 58 unseen seeds (41–160); with both, 37 of 58 (equal
// pressures 45 of 45 either way); the others stop at the cap or on a cycle — a gap front that opens a
// few nodes a step where the stack bends — and the condensed path takes over.
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
