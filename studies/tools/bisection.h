#pragma once
// The largest ε at which a monotone error is still within a tolerance, by bisection on log ε.
#include <functional>

namespace thinlayer {

struct Bracket {
  double eps_within = 0, error_within = 0;  // the largest ε known to satisfy error ≤ τ
  double eps_beyond = 0, error_beyond = 0;  // the smallest ε known to exceed τ
};

// Halves the bracket `steps` times at the geometric mean of its ends, calling error(ε) once per
// step (a layer-mode solve each, in the studies). Requires error_within ≤ tau < error_beyond
// and 0 < eps_within, eps_beyond; throws std::invalid_argument otherwise. An error that is not
// monotone inside the bracket still yields a valid bracket, of one crossing among several.
Bracket bisect_log(const std::function<double(double)>& error, Bracket bracket, double tau, int steps);

// The geometric midpoint of a bracket: the next ε bisect_log evaluates.
double log_midpoint(const Bracket& bracket);
// One bisection step: the bracket with (eps, error), evaluated at its midpoint, as a new end.
// Lets a caller evaluate the midpoints of many brackets together (in parallel), then narrow.
Bracket narrow(const Bracket& bracket, double eps, double error, double tau);

}  // namespace thinlayer
