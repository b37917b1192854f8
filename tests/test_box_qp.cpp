// The bound-constrained QP solver (core/linalg/box_qp.h) and Anderson acceleration
// (core/linalg/anderson.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Dense>

#include "core/linalg/anderson.h"
#include "core/linalg/box_qp.h"

namespace thinlayer {
namespace {

// The KKT conditions of min ½xᵀAx + bᵀx on lo ≤ x ≤ hi: feasible, and the gradient g = Ax + b
// vanishes on free variables, is ≥ 0 at lower bounds and ≤ 0 at upper ones.
double kkt_violation(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                     const Eigen::VectorXd& hi, const Eigen::VectorXd& x) {
  const Eigen::VectorXd g = A * x + b;
  double worst = 0;
  for (int i = 0; i < x.size(); ++i) {
    worst = std::max({worst, lo[i] - x[i], x[i] - hi[i]});
    const bool at_lo = x[i] <= lo[i], at_hi = x[i] >= hi[i];
    if (at_lo && at_hi) continue;
    worst = std::max(worst, at_lo ? -g[i] : at_hi ? g[i] : std::abs(g[i]));
  }
  return worst;
}

// Random SPD problems spanning six orders of magnitude in A's spectrum, with one-sided bounds
// (like r_N ≤ 0), two-sided ones (like |r_T| ≤ s) and fixed variables, from rest and warm.
TEST(BoxQP, SolvesRandomProblemsToTheirKKTConditions) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  const double inf = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 30;
    Eigen::MatrixXd Q = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
    const Eigen::MatrixXd U = qr.householderQ();
    Eigen::VectorXd spectrum(n);
    for (int i = 0; i < n; ++i) spectrum[i] = std::pow(10.0, 6.0 * i / (n - 1));
    const Eigen::MatrixXd A = U * spectrum.asDiagonal() * U.transpose();
    const Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(n, [&] { return 10 * normal(rng); });
    Eigen::VectorXd lo(n), hi(n);
    for (int i = 0; i < n; ++i) {
      if (i % 3 == 0) { lo[i] = -inf; hi[i] = 0; }
      else if (i % 3 == 1) { lo[i] = -0.1; hi[i] = 0.1; }
      else { lo[i] = hi[i] = (i % 2 ? 0.0 : 0.05); }
    }
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const BoxQPRun cold = solve_box_qp(A, b, lo, hi, x);
    ASSERT_TRUE(cold.optimal) << "trial " << trial;
    EXPECT_LT(kkt_violation(A, b, lo, hi, x), 1e-9 * b.norm()) << "trial " << trial;
    Eigen::VectorXd warm = x;
    const BoxQPRun again = solve_box_qp(A, b, lo, hi, warm);
    EXPECT_LE(again.iterations, 3) << "a warm start from the solution should stop at once";
    EXPECT_LT((warm - x).norm(), 1e-12 * std::max(1.0, x.norm()));
  }
}

// A linear fixed point x ← Mx + c whose contraction is 0.99 a step: the plain iteration needs
// thousands of steps for 1e-12, Anderson acceleration a few more than the dimension.
TEST(Anderson, AcceleratesASlowLinearFixedPoint) {
  const int n = 6;
  Eigen::VectorXd rates(n);
  rates << 0.99, 0.9, 0.5, -0.3, 0.95, 0.7;
  const Eigen::MatrixXd M = rates.asDiagonal();
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(n, 1, 2);
  const Eigen::VectorXd fixed = (Eigen::MatrixXd::Identity(n, n) - M).lu().solve(c);
  AndersonAcceleration anderson(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), plain = x;
  int steps = 0;
  for (; steps < 50 && (x - fixed).norm() > 1e-12 * fixed.norm(); ++steps) x = anderson.next(x, M * x + c);
  EXPECT_LE(steps, n + 3);
  for (int k = 0; k < steps; ++k) plain = M * plain + c;
  EXPECT_GT((plain - fixed).norm(), 1e-3 * fixed.norm()) << "the plain iteration should still be far";
}

}  // namespace
}  // namespace thinlayer
