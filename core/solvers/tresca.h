#pragma once
// Coulomb's law through Tresca's (Panagiotopoulos' fixed point, paper §4.1's ρ ← f|σ_N|): with
// the friction thresholds s frozen, the condensed problem d = g₀ + W r with Signorini and
// |r_T| ≤ s is the strictly convex quadratic program
//   min ½ rᵀ W r + g₀ᵀ r   subject to  r_N ≤ 0,  −s ≤ r_T ≤ s    (W symmetric positive definite),
// whose minimizer is unique and found without cycling (core/linalg/box_qp.h); then
// s ← f max(0, −r_N), Anderson-accelerated (the plain update oscillated at 3 % on the layer's
// case (e) at ε = 5e-3; accelerated it converged in 14 updates). The fixed point solves Coulomb.
// The floating-layer solver falls back on it where the active-set method cycles.
#include <Eigen/Core>

#include <limits>

#include "core/solvers/active_set.h"

namespace thinlayer {

struct TrescaRun {
  int threshold_updates = 0;
  int qp_iterations = 0;   // one linear solve each
  bool converged = false;  // the thresholds stopped moving: relative change below the tolerance,
                           // or below 1e-6 and no longer falling (the solves' noise)
};

// From r (warm start), on a problem with no floating unknowns; at most max_qp_iterations linear
// solves in all (the caller's budget).
TrescaRun solve_tresca_fixed_point(const Condensed& c, Eigen::VectorXd& r, int max_updates = 100,
                                   double tolerance = 1e-10,
                                   int max_qp_iterations = std::numeric_limits<int>::max());

}  // namespace thinlayer
