#include "studies/tools/bisection.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

double log_midpoint(const Bracket& b) { return std::sqrt(b.eps_within * b.eps_beyond); }

Bracket narrow(const Bracket& bracket, double eps, double error, double tau) {
  Bracket b = bracket;
  if (error <= tau) {
    b.eps_within = eps;
    b.error_within = error;
  } else {
    b.eps_beyond = eps;
    b.error_beyond = error;
  }
  return b;
}

Bracket bisect_log(const std::function<double(double)>& error, Bracket b, double tau, int steps) {
  if (!(b.eps_within > 0) || !(b.eps_beyond > 0) || !std::isfinite(b.eps_within) || !std::isfinite(b.eps_beyond))
    throw std::invalid_argument("bisect_log: the bracket's thicknesses must be finite and > 0");
  if (!(b.error_within <= tau) || !(b.error_beyond > tau))
    throw std::invalid_argument("bisect_log: the bracket must hold error <= tau at one end and > tau at the other");
  for (int i = 0; i < steps; ++i) {
    const double eps = log_midpoint(b);
    b = narrow(b, eps, error(eps), tau);
  }
  return b;
}

}  // namespace thinlayer
