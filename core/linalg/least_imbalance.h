#pragma once
// The least imbalance that forces of given kinds can leave (a linear program, GLPK):
//
//   minimise ‖G x + b‖₁   over x,   x_j ≥ 0 where column j is a ray of a cone, x_j free otherwise.
//
// Each row is one balance (a body's force along x or y, or its moment over its size); each column
// one force the scene can apply (a contact's push or a ray of its friction cone: x ≥ 0; a support's
// reaction or a bonded face's force: free); b the loads. The optimum is 0 exactly when some
// admissible forces balance every row (Farkas: otherwise a virtual motion exists along which the
// loads work and no admissible force resists). It is found by GLPK's simplex and then confirmed by
// its exact simplex (glp_exact: the same basis checked in rational arithmetic on the double data),
// so a positive optimum is a proof, not a tolerance: no admissible forces balance the loads to
// better than that. The problem is small (3 rows a body, a few columns an interface node).
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

struct LeastImbalance {
  double total = 0;             // min ‖G x + b‖₁, in the rows' units
  Eigen::VectorXd imbalance;    // G x + b at the optimum, row by row
  Eigen::VectorXd x;            // the forces of that optimum
  bool exact = false;           // confirmed by the exact (rational) simplex
};

// `free_column[j]`: column j may take either sign. `row_weight` (empty: all 1) weighs each row's
// |imbalance| in the sum minimised — which row carries it where several could — and `total` is then
// that weighted sum. Throws std::runtime_error if GLPK fails.
LeastImbalance least_imbalance(const Eigen::SparseMatrix<double>& G, const Eigen::VectorXd& b,
                               const std::vector<bool>& free_column, const Eigen::VectorXd& row_weight = {});

}  // namespace thinlayer
