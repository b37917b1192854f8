#include "core/linalg/box_qp.h"

#include <algorithm>
#include <vector>

#include <Eigen/Cholesky>

namespace thinlayer {

namespace {

enum class Bound { Free, Lower, Upper };

// The Newton step on the free variables F: A_FF p_F = −(A x + b)_F, Jacobi-scaled Cholesky
// with one step of refinement (A's diagonal can span many orders of magnitude).
Eigen::VectorXd free_step(const Eigen::MatrixXd& A, const Eigen::VectorXd& gradient, const std::vector<int>& F) {
  const int n = static_cast<int>(F.size());
  Eigen::MatrixXd A_FF(n, n);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    rhs[i] = -gradient[F[i]];
    for (int j = 0; j < n; ++j) A_FF(i, j) = A(F[i], F[j]);
  }
  const Eigen::VectorXd scale = A_FF.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::LLT<Eigen::MatrixXd> llt(scale.asDiagonal() * A_FF * scale.asDiagonal());
  Eigen::VectorXd p = scale.asDiagonal() * llt.solve(scale.asDiagonal() * rhs);
  p += scale.asDiagonal() * llt.solve(scale.asDiagonal() * (rhs - A_FF * p));
  return p;
}

}  // namespace

BoxQPRun solve_box_qp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                      const Eigen::VectorXd& hi, Eigen::VectorXd& x, int max_iterations) {
  const int n = static_cast<int>(A.rows());
  BoxQPRun run;
  x = x.cwiseMax(lo).cwiseMin(hi);
  std::vector<Bound> bound(n, Bound::Free);
  for (int i = 0; i < n; ++i) {
    if (x[i] <= lo[i]) bound[i] = Bound::Lower;
    else if (x[i] >= hi[i]) bound[i] = Bound::Upper;
  }
  bool at_face_minimizer = false;  // the last step was a full Newton step on the free variables
  for (run.iterations = 1; run.iterations <= max_iterations; ++run.iterations) {
    const Eigen::VectorXd gradient = A * x + b;
    if (at_face_minimizer) {
      // Release the bound whose multiplier has the wrong sign the most (at a lower bound the
      // gradient must be ≥ 0, at an upper bound ≤ 0), or stop: x is optimal.
      const double noise = 1e-13 * std::max(gradient.cwiseAbs().maxCoeff(), 1e-300);
      int worst = -1;
      double violation = noise;
      for (int i = 0; i < n; ++i) {
        if (lo[i] == hi[i]) continue;
        const double v = bound[i] == Bound::Lower ? -gradient[i] : bound[i] == Bound::Upper ? gradient[i] : 0.0;
        if (v > violation) {
          violation = v;
          worst = i;
        }
      }
      if (worst < 0) {
        run.optimal = true;
        return run;
      }
      bound[worst] = Bound::Free;
      at_face_minimizer = false;
      continue;
    }
    std::vector<int> F;
    for (int i = 0; i < n; ++i)
      if (bound[i] == Bound::Free) F.push_back(i);
    if (F.empty()) {
      at_face_minimizer = true;
      continue;
    }
    const Eigen::VectorXd p = free_step(A, gradient, F);
    // The longest step along p that stays in the box, and the bound that stops it.
    double alpha = 1;
    int blocking = -1;
    Bound side = Bound::Free;
    for (size_t k = 0; k < F.size(); ++k) {
      const int i = F[k];
      if (p[k] < 0 && x[i] + p[k] < lo[i] && (lo[i] - x[i]) / p[k] < alpha) {
        alpha = (lo[i] - x[i]) / p[k];
        blocking = i;
        side = Bound::Lower;
      } else if (p[k] > 0 && x[i] + p[k] > hi[i] && (hi[i] - x[i]) / p[k] < alpha) {
        alpha = (hi[i] - x[i]) / p[k];
        blocking = i;
        side = Bound::Upper;
      }
    }
    for (size_t k = 0; k < F.size(); ++k) x[F[k]] += alpha * p[k];
    if (blocking >= 0) {
      bound[blocking] = side;
      x[blocking] = side == Bound::Upper ? hi[blocking] : lo[blocking];
    }
    at_face_minimizer = blocking < 0;
  }
  run.iterations = max_iterations;
  return run;
}

}  // namespace thinlayer
