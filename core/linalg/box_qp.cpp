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

// The primal–dual active-set guess at x with multipliers from the gradient (Hintermüller, Ito &
// Kunisch): a variable is held at a bound where the bound is violated or its multiplier has
// the right sign, with the complementarity weighted by c = 1 / A_ii.
std::vector<Bound> pdas_guess(const Eigen::MatrixXd& A, const Eigen::VectorXd& gradient, const Eigen::VectorXd& lo,
                              const Eigen::VectorXd& hi, const Eigen::VectorXd& x) {
  std::vector<Bound> bound(x.size(), Bound::Free);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double trial = x[i] - gradient[i] / A(i, i);  // one coordinate Newton step
    if (trial <= lo[i]) bound[i] = Bound::Lower;
    else if (trial >= hi[i]) bound[i] = Bound::Upper;
  }
  return bound;
}

// Up to `steps` primal–dual active-set steps from x: each solves the free variables' block with
// the others at their bounds and re-guesses; true if the guess reproduced itself, x then being
// optimal. Several bounds change per step, which makes it fast from a cold or shifted start; it
// can also cycle, which the caller's primal active set cannot.
bool pdas(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
          Eigen::VectorXd& x, int steps, BoxQPRun& run) {
  std::vector<Bound> bound = pdas_guess(A, A * x + b, lo, hi, x);
  for (int step = 0; step < steps; ++step) {
    Eigen::VectorXd trial = x;
    std::vector<int> F;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      if (bound[i] == Bound::Free) F.push_back(static_cast<int>(i));
      else trial[i] = bound[i] == Bound::Lower ? lo[i] : hi[i];
      if (lo[i] == hi[i]) trial[i] = lo[i];
    }
    if (!F.empty()) {
      const Eigen::VectorXd p = free_step(A, A * trial + b, F);
      for (size_t k = 0; k < F.size(); ++k) trial[F[k]] += p[k];
    }
    ++run.iterations;
    const std::vector<Bound> next = pdas_guess(A, A * trial + b, lo, hi, trial);
    if (next == bound) {
      // A fixed point of the guess: feasible and with the right multipliers up to round-off.
      x = trial.cwiseMax(lo).cwiseMin(hi);
      return true;
    }
    bound = next;
  }
  return false;
}

}  // namespace

BoxQPRun solve_box_qp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                      const Eigen::VectorXd& hi, Eigen::VectorXd& x, int max_iterations) {
  const int n = static_cast<int>(A.rows());
  BoxQPRun run;
  // The fast primal–dual steps first, from a copy: if they settle, the primal active set below
  // only confirms the optimum (one step); if they cycle, it starts from the warm start.
  Eigen::VectorXd trial = x;
  if (pdas(A, b, lo, hi, trial, std::min(20, max_iterations), run)) x = trial;
  x = x.cwiseMax(lo).cwiseMin(hi);
  std::vector<Bound> bound(n, Bound::Free);
  for (int i = 0; i < n; ++i) {
    if (x[i] <= lo[i]) bound[i] = Bound::Lower;
    else if (x[i] >= hi[i]) bound[i] = Bound::Upper;
  }
  bool at_face_minimizer = false;  // the last step was a full Newton step on the free variables
  // At a face minimizer every bound whose multiplier has the wrong sign is released at once (a
  // cold start on the layer's problems needs hundreds of releases); a step that then cannot move
  // (α = 0, a degenerate corner) switches to the textbook one release at a time, which cannot
  // cycle.
  bool release_all = true;
  while (run.iterations < max_iterations) {  // the primal-dual steps count against the cap too
    ++run.iterations;
    const Eigen::VectorXd gradient = A * x + b;
    if (at_face_minimizer) {
      // The multipliers: at a lower bound the gradient must be ≥ 0, at an upper bound ≤ 0.
      const double noise = 1e-13 * std::max(gradient.cwiseAbs().maxCoeff(), 1e-300);
      int worst = -1;
      double violation = noise;
      std::vector<int> violated;
      for (int i = 0; i < n; ++i) {
        if (lo[i] == hi[i]) continue;
        const double v = bound[i] == Bound::Lower ? -gradient[i] : bound[i] == Bound::Upper ? gradient[i] : 0.0;
        if (v > noise) violated.push_back(i);
        if (v > violation) {
          violation = v;
          worst = i;
        }
      }
      if (worst < 0) {
        run.optimal = true;
        return run;
      }
      if (release_all) {
        for (int i : violated) bound[i] = Bound::Free;
      } else {
        bound[worst] = Bound::Free;
      }
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
    if (alpha == 0) release_all = false;
    if (blocking >= 0) {
      bound[blocking] = side;
      x[blocking] = side == Bound::Upper ? hi[blocking] : lo[blocking];
    }
    at_face_minimizer = blocking < 0;
  }
  return run;
}

}  // namespace thinlayer
