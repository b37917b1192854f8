#include "studies/tools/cauchy_rate.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

CauchyRate cauchy_rate(const std::vector<double>& eps, const std::vector<double>& difference,
                       const std::vector<bool>& converged, const TailRule& rule) {
  if (eps.size() < 2 || difference.size() + 1 != eps.size() || converged.size() != eps.size())
    throw std::invalid_argument("cauchy_rate: n thicknesses, n - 1 differences and n convergence flags needed");
  for (size_t k = 0; k + 1 < eps.size(); ++k)
    if (!(eps[k + 1] < eps[k]) || !(eps[k + 1] > 0)) throw std::invalid_argument("cauchy_rate: eps must decrease and stay > 0");
  CauchyRate rate;
  std::vector<double> tail_eps, tail_difference;
  for (size_t k = 0; k + 1 < eps.size(); ++k) {
    rate.eps.push_back(eps[k]);
    rate.difference.push_back(difference[k]);
    const bool in_tail = eps[k] <= rule.eps_max * (1 + 1e-9) && converged[k] && converged[k + 1] &&
                         std::isfinite(difference[k]) && difference[k] > 0;
    rate.in_tail.push_back(in_tail);
    if (in_tail) {
      tail_eps.push_back(eps[k]);
      tail_difference.push_back(difference[k]);
    }
  }
  if (static_cast<int>(tail_eps.size()) >= rule.min_differences) rate.fit = fit_power_law(tail_eps, tail_difference);
  return rate;
}

std::vector<double> geometric_eps_grid(int first, int last, int per_decade) {
  if (per_decade < 1 || last < first) throw std::invalid_argument("geometric_eps_grid: empty grid");
  std::vector<double> eps;
  for (int k = first; k <= last; ++k) eps.push_back(std::pow(10.0, -static_cast<double>(k) / per_decade));
  return eps;
}

}  // namespace thinlayer
