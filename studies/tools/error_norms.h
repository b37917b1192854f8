#pragma once
// Relative discrete L² distances between the two modes' fields (SPEC §3 S2).
#include <Eigen/Core>

namespace thinlayer {

// Weighted L² norm: sqrt(Σ w_k a_k²). Weights are tributary lengths (mm) on an interface, 1 at
// bulk nodes.
double weighted_norm(const Eigen::VectorXd& a, const Eigen::VectorXd& w);

// ‖a − b‖_w / max(‖b‖_w, scale · sqrt(Σ w)): relative to the reference field b where b is
// significant, and to a fixed physical scale where it vanishes — the limit law's stresses in
// case (a) and its jumps where it is rigid are zero, and a distance relative to zero would be
// infinite or meaningless. `scale` is the quantity's natural magnitude in the problem (same
// unit as a and b), so the denominator is the norm of a uniform field of that magnitude.
// Throws std::invalid_argument on mismatched sizes, negative weights or scale ≤ 0.
double relative_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& w, double scale);

}  // namespace thinlayer
