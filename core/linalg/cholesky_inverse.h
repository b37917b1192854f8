#pragma once
// S⁻¹ from the lower Cholesky factor L of S = L Lᵀ, by LAPACK's dpotri (L⁻¹ in place, then
// L⁻ᵀ L⁻¹): about (2/3) n³ flops, where forming S⁻¹ Bᵀ by triangular solves against the
// columns of Bᵀ costs n² per column — more once B has more columns than about n / 2, as for
// the Delassus operator of a body, whose interface DOFs Γ all feed the jumps.
#include <Eigen/Core>

namespace thinlayer {

// L is n × n, lower triangular (its strict upper triangle is not read). Returns S⁻¹, exactly
// symmetric. Throws std::runtime_error when L has a zero on its diagonal (S singular).
Eigen::MatrixXd cholesky_inverse(const Eigen::MatrixXd& L);

}  // namespace thinlayer
