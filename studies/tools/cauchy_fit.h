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

// The local slope between two neighbouring differences: the p at which d_k / d_{k+1} equals
// (ε_k/ε_{k+1})^p (1 − ρ_k^p)/(1 − ρ_{k+1}^p) (exactly ln(d_k/d_{k+1}) / ln(ε_k/ε_{k+1}) on a geometric
// grid; on another, the factors differ: the lap joint's ratios 2 and 2.5 alternate). Found on
// p ∈ [-4, 8]; NaN where a difference is ≤ 0 or no p in that range gives the ratio.
double cauchy_local_slope(double eps0, double eps1, double eps2, double d0, double d1);

// The rate where the grid ends (SPEC §3 S2, item 3: a rate is read where its local slopes have
// settled). q(ε) = q₀ + C ε^p + (other terms): the asymptotic rate is the slope as ε → 0, and a fit
// through the whole grid averages in the slopes of the range where another term still weighs — the
// spring model's O(ε) remainder (the bonded laws' (b), local slopes 1.05 → 0.44 along 1e-3 … 1e-6), a
// corner's own term (their (c) with one face bonded, 0.32 → 0.25 → 0.49 along 1e-4 … 1e-10):
// studies/convergence_rates.md, "The bonded laws' three misses". So:
//   fit            the Cauchy fit of the last `count` differences (count + 1 thicknesses);
//   local_slopes   one per pair of neighbouring differences, in grid order (n − 2 of them);
//   settled        the last two local slopes within `settle` of each other.
struct CauchyTail {
  std::optional<PowerLawFit> fit;
  std::vector<double> local_slopes;
  bool settled = false;
};
CauchyTail fit_cauchy_tail(const std::vector<double>& eps, const std::vector<double>& difference, int count = 3,
                           double settle = 0.1);

}  // namespace thinlayer
