#pragma once
// Two peer solvers from Siconos numerics (Debian's libsiconos-numerics-dev) run on the same
// condensed problem as solve_fast, d = g₀ + (W + C) r, so that the benchmark can compare them:
//   PeerSolver::NSGS   fc2d_driver → fc2d_nsgs_dense (non-smooth Gauss–Seidel, one contact at a
//                      time, exact 2×2 local solve)
//   PeerSolver::Lemke  fc2d_driver → fc2d_lexicolemke (the 2D problem rewritten as an LCP and
//                      solved by Lemke's pivoting method)
// Both are judged by our SPEC residual (contact_residual), never by the peer's own error.
// Scenes with a floating body (the thin-layer mode) are not supported: std::invalid_argument.
//
// What to expect on the bar (tests/test_siconos_peers.cpp): NSGS stops on its own criterion
// (how much a sweep still moves, relative to ‖q‖) some 150 times above our residual, and with
// f = 1 it does not converge at all from 64 contact nodes on; Lemke matches solve_fast to
// round-off, which grows with the size (our residual 1.4e-10 at 256 nodes). Siconos 4.4 returns
// info 0 from Lemke even when it stopped at the pivot cap: trust the residual, not the info.
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

enum class PeerSolver { NSGS, Lemke };

const char* to_string(PeerSolver solver);  // "siconos-nsgs" | "siconos-lemke"

// Solves the condensed problem with the given Siconos solver. options.tolerance and
// options.max_iterations go to the peer (0: 100000 Gauss–Seidel sweeps for NSGS, Siconos'
// default of 10000 pivots for Lemke); the report's residual, converged flag and (u, r) are in
// the project's conventions, wall_time_s is the peer's solve alone (the condensation is shared).
SolveReport solve_siconos(const ContactProblem& problem, const CondensedInterface& condensed, PeerSolver solver,
                          const SolverOptions& options = {});

}  // namespace thinlayer
