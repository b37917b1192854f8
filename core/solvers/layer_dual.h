#pragma once
// The floating layer eliminated from the condensed problem (its dual, or Delassus, operator):
// with a spring K_s holding the layer's translations towards `anchor`
// (core/solvers/floating_layer.h), its unknowns follow the forces,
//   x = (S + K_s)⁻¹ (f_L + K_s·anchor + B_Lᵀ r),
// and the jumps are a problem in r alone, like the limit mode's:
//   d = g̃ + W̃ r,   W̃ = W + B_L (S + K_s)⁻¹ B_Lᵀ (symmetric positive definite),
//   g̃ = g₀ + B_L (S + K_s)⁻¹ (f_L + K_s·anchor).
// Each row's complementarity parameter is κ = 1 / W̃_ii, the stiffness that row sees through the
// layer (with the bodies' nodal stiffness instead, a film row's decision follows its jump, which
// the smallest force on a free film moves by millimetres).
// S + K_s is factored after a Jacobi scaling: in the column basis its diagonal spans the film's
// in-plane and through-thickness stiffness (1e-13 apart at ε = 1e-8), which the scaling absorbs.
#include <Eigen/Core>

#include "core/solvers/active_set.h"

namespace thinlayer {

// The reduced problem (no floating unknowns) of c with the spring K_s anchored at `anchor`.
Condensed eliminate_layer(const Condensed& c, const Eigen::MatrixXd& K_s, const Eigen::VectorXd& anchor);

// c with the spring added to its floating part: S + K_s, f_L + K_s·anchor.
Condensed with_spring(const Condensed& c, const Eigen::MatrixXd& K_s, const Eigen::VectorXd& anchor);

}  // namespace thinlayer
