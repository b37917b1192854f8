#include "studies/tools/cauchy_fit.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

namespace {

struct Point {
  double log_eps, log_d, log_rho;
};

// ln(1 − ρ^p), and its derivative in p.
double log_factor(double log_rho, double p) { return std::log1p(-std::exp(p * log_rho)); }
double log_factor_dp(double log_rho, double p) {
  const double r = std::exp(p * log_rho);
  return -r * log_rho / (1 - r);
}

// The sum of squared residuals at p, with ln C at its best (the mean).
double misfit(const std::vector<Point>& points, double p, double* log_C = nullptr) {
  double mean = 0;
  for (const Point& q : points) mean += q.log_d - p * q.log_eps - log_factor(q.log_rho, p);
  mean /= static_cast<double>(points.size());
  double sum = 0;
  for (const Point& q : points) {
    const double r = q.log_d - mean - p * q.log_eps - log_factor(q.log_rho, p);
    sum += r * r;
  }
  if (log_C) *log_C = mean;
  return sum;
}

}  // namespace

std::optional<PowerLawFit> fit_cauchy_differences(const std::vector<double>& eps, const std::vector<double>& difference) {
  if (eps.size() < 2 || difference.size() + 1 != eps.size())
    throw std::invalid_argument("fit_cauchy_differences: need n thicknesses and n - 1 differences");
  std::vector<Point> points;
  for (std::size_t k = 0; k + 1 < eps.size(); ++k) {
    if (!(eps[k + 1] > 0) || !(eps[k + 1] < eps[k]))
      throw std::invalid_argument("fit_cauchy_differences: the thicknesses must decrease and stay > 0");
    if (difference[k] > 0) points.push_back({std::log(eps[k]), std::log(difference[k]), std::log(eps[k + 1] / eps[k])});
  }
  if (points.size() < 3) return std::nullopt;
  // A coarse scan, then refinement around the best point (the misfit is smooth in p).
  double best = 0.02, best_misfit = misfit(points, best);
  for (double p = 0.02; p <= 4.0; p += 0.01)
    if (const double m = misfit(points, p); m < best_misfit) best = p, best_misfit = m;
  for (double step = 0.005; step >= 1e-4; step /= 2)
    for (double p : {best - step, best + step})
      if (p > 0)
        if (const double m = misfit(points, p); m < best_misfit) best = p, best_misfit = m;
  PowerLawFit fit;
  fit.p = best;
  double log_C = 0;
  misfit(points, best, &log_C);
  fit.C = std::exp(log_C);
  fit.points = static_cast<int>(points.size());
  // Standard error from the residuals' derivative in p (ln C eliminated: centred).
  double mean = 0;
  std::vector<double> J;
  for (const Point& q : points) J.push_back(-q.log_eps - log_factor_dp(q.log_rho, best)), mean += J.back();
  mean /= static_cast<double>(J.size());
  double spread = 0;
  for (double j : J) spread += (j - mean) * (j - mean);
  const double s2 = best_misfit / static_cast<double>(points.size() - 2);
  fit.p_stderr = spread > 0 ? std::sqrt(s2 / spread) : 0.0;
  return fit;
}

double cauchy_local_slope(double eps0, double eps1, double eps2, double d0, double d1) {
  if (!(d0 > 0) || !(d1 > 0)) return std::nan("");
  const double log_rho0 = std::log(eps1 / eps0), log_rho1 = std::log(eps2 / eps1);
  // g(p) = ln(d0/d1) − [p ln(ε0/ε1) + ln(1 − ρ0^p) − ln(1 − ρ1^p)], continuous through p = 0
  // (where the bracket tends to ln(log_rho0 / log_rho1)) and increasing in p's bracket for p > 0.
  auto model = [&](double p) {
    if (std::abs(p) < 1e-9) return std::log(log_rho0 / log_rho1);
    return -p * log_rho0 + std::log(std::expm1(p * log_rho0) / std::expm1(p * log_rho1));  // same sign: any p
  };
  const double target = std::log(d0 / d1);
  double lo = -4, hi = 8;
  if ((model(lo) - target) * (model(hi) - target) > 0) return std::nan("");
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((model(mid) - target) * (model(lo) - target) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

CauchyTail fit_cauchy_tail(const std::vector<double>& eps, const std::vector<double>& difference, int count,
                           double settle) {
  if (count < 3) throw std::invalid_argument("fit_cauchy_tail: a fit needs at least 3 differences");
  CauchyTail tail;
  const std::size_t n = difference.size();
  if (n < static_cast<std::size_t>(count)) return tail;
  tail.fit = fit_cauchy_differences(std::vector<double>(eps.end() - count - 1, eps.end()),
                                    std::vector<double>(difference.end() - count, difference.end()));
  for (std::size_t k = 0; k + 1 < n; ++k)
    tail.local_slopes.push_back(cauchy_local_slope(eps[k], eps[k + 1], eps[k + 2], difference[k], difference[k + 1]));
  if (tail.local_slopes.size() >= 2) {
    const double a = tail.local_slopes.back(), b = tail.local_slopes[tail.local_slopes.size() - 2];
    tail.settled = std::isfinite(a) && std::isfinite(b) && std::abs(a - b) <= settle;
  }
  return tail;
}

}  // namespace thinlayer
