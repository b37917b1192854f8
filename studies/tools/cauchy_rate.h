#pragma once
// The rate of the layer model from its Cauchy differences along a geometric ε grid
// (SPEC §3 S2, item 1). With q(ε) = q₀ + C ε^p + (floor terms that do not depend on ε), the
// difference of two neighbours on a grid of ratio ρ = ε_{k+1}/ε_k is
//   ‖q(ε_k) − q(ε_{k+1})‖ ≈ C ε_k^p (1 − ρ^p),
// so the mesh floor cancels and the slope of the differences on log–log axes is p.
//
// The tail rule: a difference belongs to the fitted tail when
//   1. both of its scenes are at ε ≤ eps_max (1e-4: below it every case's layer is thin against
//      the element size h = 0.05 by a factor ≥ 500, and the ε² terms are 1e-4 of the leading
//      ones) and both reached the SPEC tolerance (fixed before any result was looked at), and
//   2. no combined status of S changes between it and the thinnest pair of converged scenes:
//      the expansion q(ε) = q₀ + C ε^p holds on one set of statuses, and a node that changes
//      status changes C (added after the first measurements, issue 14, on that ground:
//      studies/convergence_rates.md; the fit without it is kept beside, `fit_any_status`).
// The rate is measured only with at least `min_differences` such differences (3: the least that
// leaves a residual for a standard error); otherwise it is "not measurable", which a check
// counts as a failure.
#include <optional>
#include <vector>

#include "studies/tools/rate_fit.h"

namespace thinlayer {

struct TailRule {
  double eps_max = 1e-4;    // L units (mm for the bar)
  int min_differences = 3;
  bool after_status_changes = true;  // item 2 above
};

struct CauchyRate {
  std::vector<double> eps;         // ε_k: the thicker scene of each neighbouring pair
  std::vector<double> difference;  // ‖q(ε_k) − q(ε_{k+1})‖, relative (the caller's scale)
  std::vector<bool> in_tail;       // chosen by the TailRule
  std::optional<PowerLawFit> fit;  // on the tail; empty when not measurable
  // The same rule without item 2 (shown beside, so that what item 2 removes stays visible).
  std::optional<PowerLawFit> fit_any_status;
};

// `eps` is the grid, decreasing; difference[k] is between eps[k] and eps[k+1] (so one fewer);
// converged[k] whether the scene at eps[k] reached the tolerance; status_changes[k] the S nodes
// whose combined status differs between eps[k] and eps[k+1] (empty: none known).
// Throws std::invalid_argument on mismatched sizes or a grid that does not decrease.
CauchyRate cauchy_rate(const std::vector<double>& eps, const std::vector<double>& difference,
                       const std::vector<bool>& converged, const TailRule& rule = {},
                       const std::vector<int>& status_changes = {});

// The geometric grid ε_k = 10^(−k/per_decade) for k from first to last (inclusive).
std::vector<double> geometric_eps_grid(int first, int last, int per_decade);

}  // namespace thinlayer
