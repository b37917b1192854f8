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

}  // namespace thinlayer
