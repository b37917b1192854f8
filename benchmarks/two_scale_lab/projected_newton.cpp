#include "benchmarks/two_scale_lab/projected_newton.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <Eigen/Cholesky>

namespace thinlayer {

ProjectedNewtonRun solve_box_qp_projected(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Eigen::VectorXd& x,
                                          int max_iterations, const std::function<void(const Eigen::VectorXd&)>& each) {
  ProjectedNewtonRun run;
  const Eigen::Index n = x.size();
  auto project = [&](Eigen::VectorXd v) { return v.cwiseMax(lo).cwiseMin(hi); };
  auto objective = [&](const Eigen::VectorXd& v) { return 0.5 * v.dot(A * v) + b.dot(v); };
  x = project(x);
  const Eigen::VectorXd diagonal = A.diagonal().cwiseMax(1e-300);
  double scale = 0;
  for (;;) {
    const Eigen::VectorXd g = A * x + b;
    // The projected gradient, diagonally scaled: zero exactly at a minimizer.
    const Eigen::VectorXd stationarity = x - project(x - g.cwiseQuotient(diagonal));
    const double measure = stationarity.cwiseProduct(diagonal).norm();
    scale = std::max(scale, g.cwiseAbs().maxCoeff());
    if (measure <= 1e-13 * std::max(scale, 1e-300)) {
      run.optimal = true;
      break;
    }
    if (run.iterations >= max_iterations) break;
    ++run.iterations;
    if (std::getenv("PN_DETAIL") && (run.iterations < 30 || run.iterations % 50 == 0))
      std::fprintf(stderr, "      pn %d: measure %.3e (scale %.3e) objective %.10e\n", run.iterations, measure, scale,
                   objective(x));
    // The rows held: at (or within ε of) a bound with the gradient pushing outwards.
    const double epsilon = std::min(1e-8, stationarity.norm());
    std::vector<int> F;
    std::vector<bool> held(n, false);
    for (Eigen::Index i = 0; i < n; ++i) {
      held[i] = (x[i] <= lo[i] + epsilon * (1 + std::abs(lo[i])) && g[i] > 0) ||
                (x[i] >= hi[i] - epsilon * (1 + std::abs(hi[i])) && g[i] < 0) || lo[i] == hi[i];
      if (!held[i]) F.push_back(static_cast<int>(i));
    }
    Eigen::VectorXd d = -g.cwiseQuotient(diagonal);  // held rows: a scaled gradient step
    if (!F.empty()) {
      const int k = static_cast<int>(F.size());
      Eigen::MatrixXd A_FF(k, k);
      Eigen::VectorXd rhs(k);
      for (int i = 0; i < k; ++i) {
        rhs[i] = -g[F[i]];
        for (int j = 0; j < k; ++j) A_FF(i, j) = A(F[i], F[j]);
      }
      const Eigen::VectorXd s = A_FF.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
      const Eigen::LLT<Eigen::MatrixXd> llt(s.asDiagonal() * A_FF * s.asDiagonal());
      const Eigen::VectorXd step = s.asDiagonal() * llt.solve(s.asDiagonal() * rhs);
      for (int i = 0; i < k; ++i) d[F[i]] = step[i];
    }
    // Armijo along the projection arc (Bertsekas' rule: the held rows' gradient term in full).
    const double f0 = objective(x);
    double alpha = 1;
    Eigen::VectorXd trial;
    for (int backtrack = 0; backtrack < 60; ++backtrack, alpha *= 0.5) {
      trial = project(x + alpha * d);
      double decrease = 0;
      for (Eigen::Index i = 0; i < n; ++i)
        decrease += held[i] ? g[i] * (x[i] - trial[i]) : -alpha * g[i] * d[i];
      if (f0 - objective(trial) >= 1e-4 * decrease) break;
    }
    const bool moved = (trial - x).norm() > 0;
    x = trial;
    if (each) each(x);
    if (!moved) {  // at round-off: the step moves nothing
      run.optimal = true;
      break;
    }
  }
  return run;
}

}  // namespace thinlayer
