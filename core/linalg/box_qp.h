#pragma once
// A strictly convex quadratic program with bounds,
//   min ½ xᵀ A x + bᵀ x   subject to lo ≤ x ≤ hi   (A symmetric positive definite),
// by the primal active-set method (Nocedal & Wright, Numerical Optimization, Alg. 16.3): each
// step minimizes over the variables not held at a bound, stops at the first bound it meets,
// and releases a bound only at a minimizer of the current face, so the objective decreases
// monotonically and no working set repeats — no cycling, unlike a primal–dual active set on
// the same problem (measured: it cycles on the layer's Tresca problems of case (e)).
// Warm started from x (projected onto the box); lo = hi fixes a variable.
#include <Eigen/Core>

namespace thinlayer {

struct BoxQPRun {
  int iterations = 0;   // one solve with the free variables' block of A each
  bool optimal = false;
};

BoxQPRun solve_box_qp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                      const Eigen::VectorXd& hi, Eigen::VectorXd& x, int max_iterations = 2000);

}  // namespace thinlayer
