#pragma once
// The exact minimiser of one block of the Tresca energy (core/solvers/descent_blocks.h), the other
// unknowns held: the smoother of the descent method (core/solvers/tnnmg.h).
//
//   min_x ½ xᵀA x − cᵀx + Σ_rows φ_row(G_row x + g_row)
//
// with A the block's stiffness (symmetric positive definite: each column's translation is held by
// its neighbours through the film's membrane, each adherent node by its body), c the forces on it
// with the rest held. Its rows are few (two per interface node: N, T), and each row's subgradient
// condition is one of a few branches (RowState): open (λ = 0, d ≤ 0), at its kink (d = 0: contact
// λ ≥ 0, stick |λ| ≤ s, bonded any λ), or sliding (λ = +s with d ≥ 0, or λ = −s with d ≤ 0). For a
// strictly convex problem exactly one combination of branches is consistent, so each is solved as
// an equality-constrained quadratic program (one small KKT system, Jacobi-scaled, full pivoting)
// and the consistent one kept — exact, with no step length and no tolerance: where round-off leaves
// none exactly consistent, the least inconsistent (each condition's excess relative to the size of
// the terms that make it). The film's translations, whose stiffness is down to 1e-16 of the
// adherents', keep their digits: nothing is inverted but the KKT matrix, pivoted on its largest
// entries, the constraints' couplings first.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/descent_blocks.h"

namespace thinlayer {

// A row's branch. λ is the row's multiplier, r = −λ its force on the plus side.
enum class RowState {
  Open,   // λ = 0 (an obstacle row off its kink, or a free row)
  Kink,   // d = 0 (contact, stick, bonded)
  Plus,   // λ = +s, d ≥ 0 (a slide whose jump is positive)
  Minus,  // λ = −s, d ≤ 0
};

struct BlockProblem {
  Eigen::MatrixXd A;             // n × n
  Eigen::VectorXd c;             // n
  Eigen::MatrixXd G;             // rows × n
  Eigen::VectorXd g;             // rows
  std::vector<RowKind> kind;     // per row
  Eigen::VectorXd s;             // per row: the threshold of a Friction row
};

struct BlockMinimum {
  Eigen::VectorXd x;
  Eigen::VectorXd lambda;            // per row
  std::vector<RowState> state;       // per row
  double inconsistency = 0;          // the largest relative excess of the branch kept (0: exact)
  int branches_solved = 0;
};

// `guess` (one state per row, or empty): tried first, and kept if exactly consistent.
BlockMinimum minimise_block(const BlockProblem& problem, const std::vector<RowState>& guess = {});

// The projection of x̂ onto the block's domain {x : d ≤ 0 on its Obstacle rows, d = 0 on its Equality
// rows} in the block's energy norm, min ½ (x − x̂)ᵀA(x − x̂) (TNNMG's projection of the correction onto
// dom φ, blockwise): in the energy norm the projection moves what is soft — a film column's
// translation — rather than the adherent nodes or the film's through-thickness levels, which a
// Euclidean projection moves as much and which the line search then has to undo at their stiffness.
// Each subset of the obstacle rows taken as active is one KKT solve (as minimise_block's); the one
// whose multipliers are ≥ 0 and whose other rows are feasible is the projection.
Eigen::VectorXd project_to_domain(const Eigen::MatrixXd& A, const Eigen::MatrixXd& G, const Eigen::VectorXd& g,
                                  const std::vector<RowKind>& kind, const Eigen::VectorXd& x_hat);

}  // namespace thinlayer
