#include "studies/tools/cauchy_rate.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

namespace {

// Item 1 of the tail rule: thin enough, both scenes converged, a difference that can be fitted.
bool thin_and_converged(const std::vector<double>& eps, const std::vector<double>& difference,
                        const std::vector<bool>& converged, const TailRule& rule, size_t k) {
  return eps[k] <= rule.eps_max * (1 + 1e-9) && converged[k] && converged[k + 1] && std::isfinite(difference[k]) &&
         difference[k] > 0;
}

std::optional<PowerLawFit> fit_on(const CauchyRate& rate, const std::vector<bool>& keep, int min_differences) {
  std::vector<double> eps, difference;
  for (size_t k = 0; k < keep.size(); ++k)
    if (keep[k]) {
      eps.push_back(rate.eps[k]);
      difference.push_back(rate.difference[k]);
    }
  if (static_cast<int>(eps.size()) < min_differences) return std::nullopt;
  return fit_power_law(eps, difference);
}

}  // namespace

CauchyRate cauchy_rate(const std::vector<double>& eps, const std::vector<double>& difference,
                       const std::vector<bool>& converged, const TailRule& rule, const std::vector<int>& status_changes) {
  if (eps.size() < 2 || difference.size() + 1 != eps.size() || converged.size() != eps.size())
    throw std::invalid_argument("cauchy_rate: n thicknesses, n - 1 differences and n convergence flags needed");
  if (!status_changes.empty() && status_changes.size() != difference.size())
    throw std::invalid_argument("cauchy_rate: one status-change count per difference");
  for (size_t k = 0; k + 1 < eps.size(); ++k)
    if (!(eps[k + 1] < eps[k]) || !(eps[k + 1] > 0)) throw std::invalid_argument("cauchy_rate: eps must decrease and stay > 0");
  CauchyRate rate;
  rate.eps.assign(eps.begin(), eps.end() - 1);
  rate.difference = difference;
  std::vector<bool> thin(difference.size());
  for (size_t k = 0; k < difference.size(); ++k) thin[k] = thin_and_converged(eps, difference, converged, rule, k);
  // Item 2: walking up from the thinnest pair, the tail stops at the first converged pair whose
  // statuses differ (that pair and every thicker one are left out).
  rate.in_tail = thin;
  bool changed = false;
  for (size_t k = difference.size(); k-- > 0;) {
    const bool both_converged = converged[k] && converged[k + 1];
    changed = changed || (rule.after_status_changes && both_converged && !status_changes.empty() && status_changes[k] > 0);
    rate.in_tail[k] = thin[k] && !changed;
  }
  rate.fit = fit_on(rate, rate.in_tail, rule.min_differences);
  rate.fit_any_status = fit_on(rate, thin, rule.min_differences);
  return rate;
}

std::vector<double> geometric_eps_grid(int first, int last, int per_decade) {
  if (per_decade < 1 || last < first) throw std::invalid_argument("geometric_eps_grid: empty grid");
  std::vector<double> eps;
  for (int k = first; k <= last; ++k) eps.push_back(std::pow(10.0, -static_cast<double>(k) / per_decade));
  return eps;
}

}  // namespace thinlayer
