#pragma once
// The exact minimiser of the Tresca energy (core/solvers/descent_blocks.h) along a correction:
//   φ(α) = J_s(y + α Δ),  α ∈ [0, α_max],
// a convex piecewise quadratic, on a segment whose both ends are feasible (the correction is projected
// onto the obstacle rows' domain first, core/solvers/block_minimiser.h: the segment is then feasible,
// the domain being convex). Its derivative
//   φ'(α) = Δᵀ(K_y y − F_y) + α ΔᵀK_yΔ + Σ_friction s_i Δd_i sign(d_i + α Δd_i)
// is increasing and jumps at the breakpoints α_i = −d_i/Δd_i of the friction rows; the minimiser is
// where it changes sign, found by walking the sorted breakpoints. Every sum is carried in extended
// precision and φ itself is never compared: at the film's scale, energy differences are below the
// round-off of the energy (the adherents' share), derivatives are not.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/solvers/block_minimiser.h"

namespace thinlayer {

struct KinkLineSearch {
  double alpha = 0;       // the step taken
  double alpha_max = 0;   // the segment's end
  bool clipped = false;   // the minimiser lies at α_max (the whole step)
  int breakpoints = 0;    // friction kinks crossed
  double slope_at_zero = 0;  // φ'(0+): ≥ 0 means Δ is no descent direction
};

KinkLineSearch kink_line_search(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& F,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B, const Eigen::VectorXd& g_D,
                                const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold,
                                const Eigen::VectorXd& y, const Eigen::VectorXd& delta, double alpha_max = 1);

}  // namespace thinlayer
