#pragma once
// The rate of the layer model from the differences of neighbouring thicknesses on any
// decreasing grid (a scene file's ε list need not be geometric). With q(ε) = q₀ + C ε^p + (a floor
// that does not depend on ε), neighbours ε_k > ε_{k+1} differ by
//   d_k = ‖q(ε_k) − q(ε_{k+1})‖ ≈ C ε_k^p (1 − ρ_k^p),   ρ_k = ε_{k+1} / ε_k,
// so the floor cancels (SPEC §3 S2, item 1; on a geometric grid this is studies/tools/cauchy_rate.h).
// p is fitted by least squares on ln d_k (the best ln C for each p is their mean), searched on
// p ∈ [0.02, 4] to 1e-4; its standard error from the linearised residuals.
#include <optional>
#include <vector>

#include "studies/tools/rate_fit.h"

namespace thinlayer {

// eps: the grid, decreasing (n values); difference[k] between eps[k] and eps[k+1] (n − 1 values).
// Differences ≤ 0 are left out; empty with fewer than 3 left. Throws std::invalid_argument on
// mismatched sizes or a grid that does not decrease.
std::optional<PowerLawFit> fit_cauchy_differences(const std::vector<double>& eps, const std::vector<double>& difference);

}  // namespace thinlayer
