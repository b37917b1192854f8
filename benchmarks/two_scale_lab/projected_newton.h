#pragma once
// Issue 33's second experiment (the gate's fall-back): a globally convergent method over every
// row. The layer eliminated with a selection spring (core/solvers/layer_dual.h), Coulomb by the
// Tresca fixed point, each Tresca problem — min ½ rᵀ W̃ r + g̃ᵀ r over the box r_N ≤ 0, |r_T| ≤ s —
// by Bertsekas' projected Newton method (SIAM J. Control Optim. 20, 1982): a Newton step on the
// rows not held at a bound, a scaled gradient step on the held ones, projected onto the box, with
// an Armijo search along the projection arc. It converges from any start and, unlike the primal
// active set (core/linalg/box_qp.h, one bound a step), changes many bounds a step: a truncated
// nonsmooth Newton method of the TNNMG kind on the dual, where the box is separable.
#include <functional>

#include <Eigen/Core>

namespace thinlayer {

struct ProjectedNewtonRun {
  int iterations = 0;      // dense solves of the free rows' block
  bool optimal = false;    // the projected gradient vanished (relative 1e-14)
};

// min ½ xᵀ A x + bᵀ x over lo ≤ x ≤ hi from x; `each` is called after every iteration.
ProjectedNewtonRun solve_box_qp_projected(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Eigen::VectorXd& x,
                                          int max_iterations, const std::function<void(const Eigen::VectorXd&)>& each);

}  // namespace thinlayer
