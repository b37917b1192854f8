#pragma once
// The Tresca energy of a layer problem and its blocks, for the descent method (core/solvers/tnnmg.h).
//
// With the friction thresholds s frozen, the answer of the layer problem minimises
//   J_s(y) = ½ yᵀK_y y − F_yᵀ y + Σ_rows φ_row(d_row),   d = B_y y + g_D,
// over y (the adherents' free DOFs nodally, each layer band in its column basis:
// core/solvers/mixed_system.h), where each interface row contributes (RowKind):
//   - Obstacle: a normal row of a contact face, φ = χ(d ≤ 0)  (Signorini: [u]_N > 0 is interpenetration);
//   - Friction: a tangential row of a contact face with threshold s > 0, φ = s |d|  (Tresca);
//   - Equality: a row of a bonded face, φ = χ(d = 0);
//   - Free: a row that carries no force (a law without that stiffness, or s = 0), φ = 0.
// J_s is convex; its subgradient condition is K_y y − F_y + B_yᵀ λ = 0, λ ∈ ∂φ(d), and the
// interface forces are r = −λ (K u = F + Bᵀ r, r_N ≤ 0 in compression, r_T = −s sign d_T on a slide).
// The laws must be rigid (C = 0) or free (no force): a finite spring's energy is not a function of
// the jump of y alone in this form; such problems are not this method's (layer_descent_applies).
//
// The blocks: one per film column of a layer band, with the adherent nodes facing its two ends,
// so that every jump row lies inside one block and the nonsmooth part is a sum over blocks (a
// change to jump coordinates would instead cancel (ε/h)² of the film's translation in round-off).
// Columns that share an adherent node (bondlines meeting) form one block. The unknowns in no block
// — the adherents off S — form the smooth interior, solved by one Cholesky factor.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

enum class RowKind { Free, Obstacle, Friction, Equality };

// The energy's rows for thresholds s (one per node, force unit; ignored where the law has no friction).
std::vector<RowKind> tresca_rows(const ContactProblem& problem, const Eigen::VectorXd& s);

// Does the descent method apply: every interface row rigid or free (no finite spring), and at
// least one layer band?
bool layer_descent_applies(const ContactProblem& problem);

struct DescentBlock {
  std::vector<int> y;      // its unknowns (indices into y), increasing
  std::vector<int> rows;   // the interface rows that lie in it (2 per node: N, T)
};

struct DescentBlocks {
  std::vector<DescentBlock> blocks;
  std::vector<int> interior;  // the unknowns in no block
  std::vector<int> block_of_row;  // each interface row's block
};

DescentBlocks descent_blocks(const MixedSystem& mixed);

}  // namespace thinlayer
