#include "studies/tools/rate_fit.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <Eigen/Dense>

#include "studies/tools/format.h"

namespace thinlayer {

std::optional<PowerLawFit> fit_power_law(const std::vector<double>& eps, const std::vector<double>& error) {
  if (eps.size() != error.size()) throw std::invalid_argument("fit_power_law: as many errors as thicknesses needed");
  std::vector<double> x, y;
  for (size_t i = 0; i < eps.size(); ++i) {
    if (!(eps[i] > 0) || !std::isfinite(eps[i])) throw std::invalid_argument("fit_power_law: eps must be finite and > 0");
    if (error[i] > 0 && std::isfinite(error[i])) {
      x.push_back(std::log(eps[i]));
      y.push_back(std::log(error[i]));
    }
  }
  const int n = static_cast<int>(x.size());
  if (n < 3) return std::nullopt;
  double mx = 0, my = 0;
  for (int i = 0; i < n; ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0)) return std::nullopt;  // all points at one ε
  PowerLawFit fit;
  fit.points = n;
  fit.p = sxy / sxx;
  const double intercept = my - fit.p * mx;
  fit.C = std::exp(intercept);
  double ss = 0;
  for (int i = 0; i < n; ++i) {
    const double r = y[i] - (intercept + fit.p * x[i]);
    ss += r * r;
  }
  fit.p_stderr = std::sqrt(ss / (n - 2) / sxx);
  return fit;
}

namespace {

struct FloorFit {
  double floor = 0, C = 0, ss = INFINITY;
};

// The best (floor ≥ 0, C) for a fixed p, on relative residuals.
FloorFit fit_at(double p, const std::vector<double>& eps, const std::vector<double>& e) {
  const int n = static_cast<int>(eps.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    A(i, 0) = 1 / e[i];
    A(i, 1) = std::pow(eps[i], p) / e[i];
    b[i] = 1;
  }
  FloorFit f;
  Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
  if (x[0] < 0) {  // the floor is bounded below by 0: refit without it
    x[0] = 0;
    x[1] = A.col(1).dot(b) / A.col(1).squaredNorm();
  }
  f.floor = x[0];
  f.C = x[1];
  f.ss = (A * x - b).squaredNorm();
  return f;
}

}  // namespace

std::optional<FlooredPowerLawFit> fit_power_law_with_floor(const std::vector<double>& eps,
                                                          const std::vector<double>& error) {
  if (eps.size() != error.size()) throw std::invalid_argument("fit_power_law_with_floor: sizes differ");
  std::vector<double> x, y;
  for (size_t i = 0; i < eps.size(); ++i) {
    if (!(eps[i] > 0) || !std::isfinite(eps[i])) throw std::invalid_argument("fit_power_law_with_floor: eps must be > 0");
    if (error[i] > 0 && std::isfinite(error[i])) {
      x.push_back(eps[i]);
      y.push_back(error[i]);
    }
  }
  const int n = static_cast<int>(x.size());
  if (n < 4) return std::nullopt;
  double best_p = 0;
  FloorFit best;
  for (double p = 0.02; p <= 4.0 + 1e-12; p += 0.02) {
    const FloorFit f = fit_at(p, x, y);
    if (f.ss < best.ss) best = f, best_p = p;
  }
  for (double step = 0.01; step > 1e-6; step *= 0.5)  // refine: golden enough for a smooth 1-D minimum
    for (double p : {best_p - step, best_p + step}) {
      if (p <= 0) continue;
      const FloorFit f = fit_at(p, x, y);
      if (f.ss < best.ss) best = f, best_p = p;
    }
  FlooredPowerLawFit fit;
  fit.p = best_p;
  fit.C = best.C;
  fit.floor = best.floor;
  fit.points = n;
  // Jacobian of the relative residuals r_i = (floor + C ε_i^p)/e_i − 1 in (floor, C, p).
  Eigen::MatrixXd J(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = std::pow(x[i], best_p);
    J(i, 0) = 1 / y[i];
    J(i, 1) = t / y[i];
    J(i, 2) = best.C * t * std::log(x[i]) / y[i];
  }
  // A floor pinned at 0 is not a free parameter: drop its column.
  const Eigen::MatrixXd Jf = best.floor > 0 ? J : J.rightCols(2);
  const int dof = n - static_cast<int>(Jf.cols());
  const double s2 = dof > 0 ? best.ss / dof : 0;
  const Eigen::MatrixXd cov = s2 * (Jf.transpose() * Jf).inverse();
  fit.p_stderr = std::sqrt(std::max(0.0, cov(cov.rows() - 1, cov.cols() - 1)));
  return fit;
}

namespace {

template <class Fit>
std::string rate_text_of(const std::optional<Fit>& f) {
  if (!f) return "n/a";
  char s[64];
  std::snprintf(s, sizeof s, "%.2f±%.2f", f->p, f->p_stderr);
  return s;
}

}  // namespace

std::string rate_text(const std::optional<PowerLawFit>& fit) { return rate_text_of(fit); }
std::string rate_text(const std::optional<FlooredPowerLawFit>& fit) { return rate_text_of(fit); }

void print_fit_rows(const std::vector<std::string>& quantities,
                    const std::map<std::string, std::optional<PowerLawFit>>& fit,
                    const std::map<std::string, std::optional<FlooredPowerLawFit>>& floor_fit, int label_width,
                    int column_width) {
  std::printf("  %-*s", label_width, "p");
  for (const std::string& q : quantities) std::printf(" %*s", column_width, rate_text(fit.at(q)).c_str());
  std::printf("\n  %-*s", label_width, "p floor");
  for (const std::string& q : quantities) std::printf(" %*s", column_width, rate_text(floor_fit.at(q)).c_str());
  std::printf("\n  %-*s", label_width, "e_inf");
  for (const std::string& q : quantities) {
    const auto& f = floor_fit.at(q);
    std::printf(" %*s", column_width, f ? sci(f->floor, 2).c_str() : "n/a");
  }
  std::printf("\n");
}

}  // namespace thinlayer
