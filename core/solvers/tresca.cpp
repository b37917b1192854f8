#include "core/solvers/tresca.h"

#include <algorithm>
#include <limits>

#include "core/linalg/anderson.h"
#include "core/linalg/box_qp.h"

namespace thinlayer {

namespace {

Eigen::VectorXd thresholds(const Condensed& c, const Eigen::VectorXd& r) {
  const int m = static_cast<int>(c.normal.size());
  Eigen::VectorXd s(m);
  for (int k = 0; k < m; ++k) s[k] = c.tangential[k] ? c.friction[k] * std::max(0.0, -r[2 * k]) : 0.0;
  return s;
}

}  // namespace

TrescaRun solve_tresca_fixed_point(const Condensed& c, Eigen::VectorXd& r, int max_updates, double tolerance,
                                   int max_qp_iterations) {
  const int m = static_cast<int>(c.normal.size());
  const double infinity = std::numeric_limits<double>::infinity();
  TrescaRun run;
  AndersonAcceleration anderson(5);
  Eigen::VectorXd s = thresholds(c, r), lo(2 * m), hi(2 * m);
  // The thresholds' change can only fall to the noise of the QP's solves (W's condition number
  // times round-off: 1e-9 at the layer's spring 1e-8 κ): once it has not halved over
  // `stalled_limit` updates it is at that floor, and further updates only repeat it.
  constexpr int stalled_limit = 5;
  double best_change = std::numeric_limits<double>::infinity();
  int stalled = 0;
  for (run.threshold_updates = 1; run.threshold_updates <= max_updates; ++run.threshold_updates) {
    for (int k = 0; k < m; ++k) {
      lo[2 * k] = c.normal[k] ? -infinity : 0.0;  // r_N ≤ 0 (0 where the law has no normal force)
      hi[2 * k] = 0.0;
      lo[2 * k + 1] = -s[k];
      hi[2 * k + 1] = s[k];
    }
    if (run.qp_iterations >= max_qp_iterations) break;
    const BoxQPRun qp = solve_box_qp(c.W, c.g0, lo, hi, r, max_qp_iterations - run.qp_iterations);
    run.qp_iterations += qp.iterations;
    const Eigen::VectorXd image = thresholds(c, r);
    const double change = (image - s).norm() / std::max(image.norm(), 1e-300);
    if (qp.optimal && change <= tolerance) {
      run.converged = true;
      break;
    }
    if (change < 0.5 * best_change) {
      best_change = change;
      stalled = 0;
    } else if (++stalled >= stalled_limit) {
      run.converged = qp.optimal && best_change <= 1e-6;  // converged to the solves' noise
      break;
    }
    s = anderson.next(s, image).cwiseMax(0.0);
  }
  run.threshold_updates = std::min(run.threshold_updates, max_updates);
  return run;
}

}  // namespace thinlayer
